#!/usr/bin/env bash
# Checks (default) or applies (--apply) the tree's clang-format style (.clang-format, VTK's) on
# the C++ sources of the plugin, its readers, tests and benchmarks. Generated and fetched code
# is not ours to format. Exit status 1 with the files that differ.
#   bash Scripts/check_format.sh [--apply | --self-test]
# --self-test: the check must reject a misformatted file (run by CTest beside the check).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
format=${CLANG_FORMAT:-clang-format}
mapfile -t files < <(cd "$top" && find Representations Readers Plugin Testing Benchmarks \
  -type f \( -name '*.h' -o -name '*.cxx' \) | LC_ALL=C sort)
cd "$top"
if [ "${1:-}" = "--self-test" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  cp "$top/.clang-format" "$tmp/"
  printf 'int vtkBadlyFormatted( int a ){ if(a){return  1;} return 0; }\n' > "$tmp/bad.cxx"
  if "$format" --style=file --dry-run --Werror "$tmp/bad.cxx" > /dev/null 2>&1; then
    echo "check_format: self-test: a misformatted file passed the check" >&2
    exit 1
  fi
  "$format" -i --style=file "$tmp/bad.cxx"
  "$format" --style=file --dry-run --Werror "$tmp/bad.cxx"
  echo "check_format: self-test: the misformatted file is rejected, its formatted copy accepted"
  exit 0
fi
if [ "${1:-}" = "--apply" ]; then
  "$format" -i --style=file "${files[@]}"
  echo "check_format: formatted ${#files[@]} files with $("$format" --version)"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  if ! "$format" --style=file --dry-run --Werror "$f" > /dev/null 2>&1; then
    bad+=("$f")
  fi
done
if [ ${#bad[@]} -gt 0 ]; then
  printf 'check_format: not formatted: %s\n' "${bad[@]}"
  echo "check_format: ${#bad[@]} of ${#files[@]} files differ from .clang-format (run: bash Scripts/check_format.sh --apply)"
  exit 1
fi
echo "check_format: ${#files[@]} files formatted ($("$format" --version))"
