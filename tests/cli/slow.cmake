# SPDX-License-Identifier: Apache-2.0
# The slowest command-line tests (label slow), each with its cost: seconds
# measured under AddressSanitizer, where they are slowest. ctest starts the
# costliest first, so on a fresh build tree (no timings of its own yet) the
# long tests do not end up last, alone on one core. `ctest -LE slow` skips
# them.
function(cmfilter_slow_test name cost)
  set_property(TEST cli.${name} PROPERTY COST ${cost})
  set_property(TEST cli.${name} APPEND PROPERTY LABELS slow)
endfunction()
cmfilter_slow_test(bench.small 110)
cmfilter_slow_test(faults.kill-table 60)
cmfilter_slow_test(faults.concurrent-writers 65)
cmfilter_slow_test(faults.kill-render 30)
cmfilter_slow_test(faults.kill-moments 15)
cmfilter_slow_test(faults.full-disk 25)
cmfilter_slow_test(render.bad.tolerance-unreachable 30)
cmfilter_slow_test(tolerance.terrain 30)
cmfilter_slow_test(stacks.bundled 30)
cmfilter_slow_test(render.tolerance 26)
cmfilter_slow_test(render.tolerance-json 26)
cmfilter_slow_test(determinism.bake-colormap-tolerance 26)
cmfilter_slow_test(lafortune.btf-slot 25)
cmfilter_slow_test(bad.tolerance-impossible 21)
cmfilter_slow_test(lafortune.near-diffuse 16)
cmfilter_slow_test(determinism.bake-colormap 14)
cmfilter_slow_test(tolerance.for-sigma-table 12)
