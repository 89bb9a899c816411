# SPDX-License-Identifier: Apache-2.0
# Farm scale (docs/farm.md): regions of a render (render --region) stitched
# with oiiotool are the whole render bit for bit, image and AOVs, for every
# method, the frame at 1 thread and the regions at 2; bench's references by
# region likewise; the farm example (examples/farm/) on this machine alone
# and as Slurm job arrays on a single-node cluster the test stands up and
# takes down (label slurm).
set(STITCH ${CMAKE_CURRENT_SOURCE_DIR}/check_region_stitch.sh)

# cmfilter_stitch_case(<name> <scene> <fixtures> <render options> -- <control options>)
# The whole frame is rendered with 1 thread and the regions with 2, so each
# test checks a thread count against another as well as regions against the
# frame (render's own determinism tests cover more thread counts).
function(cmfilter_stitch_case name scene fixtures)
  add_test(NAME cli.farm.stitch-${name}
           COMMAND bash ${STITCH} ${CMF} ${scene} ${OUT}/farm-stitch-${name} 2 -- ${ARGN})
  set_tests_properties(cli.farm.stitch-${name} PROPERTIES
                       FIXTURES_REQUIRED "cli_dirs;cli_fixtures;${fixtures}" LABELS cli ENVIRONMENT "OCIO=")
endfunction()
# Each with a control that must change the region it renders: another method,
# or for the ray-traced methods another seed.
cmfilter_stitch_case(naive ${SC}/good.json "" --method naive -- --method gaussian)
cmfilter_stitch_case(gaussian ${SC}/good.json "" --method gaussian -- --method naive)
cmfilter_stitch_case(supersample ${SC}/good.json "" --method supersample --spp 5 -- --method supersample --spp 5 --seed 1)
cmfilter_stitch_case(reference ${SC}/good.json "" --method reference -- --method reference --seed 1)
cmfilter_stitch_case(exact ${SCB}/texture-quantised.json "" --method exact -- --method naive)
# --method auto chooses from the whole frame's LODs, so every tile chooses
# alike: here the frame's LODs -5 to 0 take 4 x 4 squares at DE 2, where the
# near tiles' own LODs (-5 to -3) would take 2 x 2.
cmfilter_stitch_case(auto-noise ${SCB}/noise-auto-tilted.json "" --method auto --tolerance 2 -- --method gaussian)
cmfilter_stitch_case(microsurface-gaussian-exact ${MICRO_SCENE} microsurface_scene --method gaussian-exact
                     -- --method gaussian)
cmfilter_stitch_case(microsurface-supersample ${MICRO_SCENE} microsurface_scene --method supersample --spp 4
                     -- --method supersample --spp 4 --seed 1)

add_test(NAME cli.farm.bench-references
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_bench_region.sh ${CMF} ${SC}/good.json
                 ${OUT}/farm-bench-references)
set_tests_properties(cli.farm.bench-references PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures" LABELS cli
                     ENVIRONMENT "OCIO=")

# The example: the bundled far sphere's reference in 3 x 2 tiles and every
# one-row map of luts/ baked, each task a command line; here in a local
# loop, then on Slurm.
set(FARM_CHECK ${CMAKE_CURRENT_SOURCE_DIR}/check_farm_example.sh)
add_test(NAME cli.farm.example-local
         COMMAND bash ${FARM_CHECK} --local ${CMF} ${OUT}/farm-example-local --size 96x96 --tiles 3x2)
set_tests_properties(cli.farm.example-local PROPERTIES FIXTURES_REQUIRED cli_dirs LABELS cli
                     ENVIRONMENT "OCIO=" TIMEOUT 300)
add_test(NAME cli.farm.example-slurm
         COMMAND bash ${FARM_CHECK} --slurm ${CMF} ${OUT}/farm-example-slurm --size 160x160 --tiles 3x2)
set_tests_properties(cli.farm.example-slurm PROPERTIES FIXTURES_REQUIRED cli_dirs LABELS "cli;slurm"
                     ENVIRONMENT "OCIO=" TIMEOUT 300)
