# ParticleRendering.Benchmark.Smoke: the benchmark drivers must start and render a tiny data set
# (no timing or error asserted). Run from the test's working directory (the error CSV goes there):
#   cmake -DOPAQUE=<prBenchmark> -DTRANSLUCENT=<prTransparentBenchmark> -DDATA=<particles.vtp>
#     -P BenchmarkSmoke.cmake
file(REMOVE smoke_transparent_errors.csv)
foreach (command IN ITEMS
    "${OPAQUE};--data;${DATA};--frames;2;--size;200x150;--color-array;type"
    "${TRANSLUCENT};--data;${DATA};--max-particles;1000;--frames;1;--static-frames;1;--size;200x150;--color-array;type"
    "${TRANSLUCENT};--data;${DATA};--max-particles;1000;--size;200x150;--color-array;type;--errors;smoke_transparent_errors.csv")
  execute_process(COMMAND ${command} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${command}")
  endif ()
endforeach ()
