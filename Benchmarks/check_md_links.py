#!/usr/bin/env python3
"""Check that every relative Markdown link in Benchmarks/*.md resolves: the file (relative to
Benchmarks/) exists and, for links with #anchor into a .md file, that file has a heading with that
GitHub anchor. usage: python3 Benchmarks/check_md_links.py   (exit 1 and a list when some fail)"""
import glob
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def slug(heading):
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def anchors(path):
    found, seen = set(), {}
    in_code = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_code = not in_code
            if in_code or not line.startswith("#"):
                continue
            base = slug(line.lstrip("#"))
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else "%s-%d" % (base, n))
    return found


def main():
    bad, count = [], 0
    for md in sorted(glob.glob(os.path.join(HERE, "*.md"))):
        with open(md, encoding="utf-8") as f:
            text = f.read()
        for target in LINK.findall(text):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, https:, mailto:
            count += 1
            path, _, anchor = target.partition("#")
            full = os.path.normpath(os.path.join(HERE, path)) if path else md
            if not os.path.exists(full):
                bad.append("%s: %s (no such file)" % (os.path.basename(md), target))
            elif anchor and full.endswith(".md") and anchor not in anchors(full):
                bad.append("%s: %s (no such heading)" % (os.path.basename(md), target))
    for line in bad:
        print(line)
    print("%d relative links checked, %d broken" % (count, len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
