# SPDX-License-Identifier: Apache-2.0
# Inputs that declare huge sizes are refused before the allocation, with the
# limit named (util/memory_budget.h): an image header claiming 100000 x 100000
# pixels, a scene at the largest resolution, a stack of 10000 images. Each
# is refused under CMFILTER_MEMORY_LIMIT (every build) and, in a plain build,
# under `ulimit -v` (sanitizers need the address space `ulimit -v` takes).
set(LIM ${OUT}/limits)
add_test(NAME cli.limits.fixtures
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/make_limit_fixtures.py ${LIM})
set_tests_properties(cli.limits.fixtures PROPERTIES FIXTURES_SETUP limit_fixtures FIXTURES_REQUIRED cli_dirs
                     LABELS cli)

# cmfilter_limit_case(<name> <stderr ERE> <output> <args>...): refused with
# exit 3 under a 1 GB CMFILTER_MEMORY_LIMIT and under ulimit -v 2 GB.
function(cmfilter_limit_case name err output)
  cmfilter_cli_case(NAME limits.${name}.env EXIT 3 STDERR "${err}.*CMFILTER_MEMORY_LIMIT=1G" ABSENT ${output}
                    COMMAND env CMFILTER_MEMORY_LIMIT=1G ${ARGN})
  set_tests_properties(cli.limits.${name}.env PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;limit_fixtures")
  if(NOT CMFILTER_SANITIZE)
    cmfilter_cli_case(NAME limits.${name}.ulimit EXIT 3 STDERR "${err}.*ulimit -v" ABSENT ${output}
                      COMMAND bash -c "ulimit -v 2000000 && exec \"$@\"" _ ${ARGN})
    set_tests_properties(cli.limits.${name}.ulimit PROPERTIES
                         FIXTURES_REQUIRED "cli_dirs;cli_fixtures;limit_fixtures")
  endif()
endfunction()

set(HUGE_PNG "'.*huge\\.png' \\(100000 x 100000 pixels, 3 channels\\) needs 120 GB, more than the")
cmfilter_limit_case(image-bake-colormap "${HUGE_PNG}" ${LIM}/table.exr
                    ${CMF} bake-colormap ${LIM}/huge.png -o ${LIM}/table.exr)
cmfilter_limit_case(image-bake-moments "'.*huge\\.png' \\(100000 x 100000 pixels, 1 channel\\) needs 40 GB"
                    ${LIM}/moments.exr ${CMF} bake-moments ${LIM}/huge.png --channel 0 -o ${LIM}/moments.exr)
cmfilter_limit_case(image-synth-analyse "${HUGE_PNG}" ${LIM}/analysis.exr
                    ${CMF} synth-analyse ${LIM}/huge.png -o ${LIM}/analysis.exr)
cmfilter_limit_case(image-compare "${HUGE_PNG}" ${LIM}/heat.png
                    ${CMF} compare ${LIM}/huge.png ${LIM}/huge.png --heatmap ${LIM}/heat.png)
cmfilter_limit_case(scene-resolution "the render of '.*huge-scene\\.json' \\(16384 x 4096 pixels\\) needs 4\\.3 GB"
                    ${LIM}/render.exr ${CMF} render ${LIM}/huge-scene.json -o ${LIM}/render.exr)
# A Lafortune fit holds every image of its stack: refused. A linear fit
# streams them (streamed_fit.h): 10000 images fit in bounded memory, under the
# same limit (16 x 16 images, to keep the test short).
cmfilter_limit_case(stack-10000-images "the stack '.*many\\.lp' \\(10000 images of 256 x 128 x 3\\) needs 3\\.9 GB"
                    ${LIM}/fit.exr ${CMF} fit ${LIM}/many.lp --model lafortune -o ${LIM}/fit.exr)
if(NOT CMFILTER_SANITIZE)
  cmfilter_cli_case(NAME limits.stack-10000-images.streamed EXIT 0 STDOUT "ptm-rgb fit, 16 x 16, 3 channels"
                    COMMAND bash -c "ulimit -v 2000000 && exec \"$@\"" _ ${CMF} fit ${LIM}/many-small.lp
                            --model ptm-rgb -o ${LIM}/fit-streamed.exr)
  set_tests_properties(cli.limits.stack-10000-images.streamed PROPERTIES
                       FIXTURES_REQUIRED "cli_dirs;cli_fixtures;limit_fixtures")
endif()
