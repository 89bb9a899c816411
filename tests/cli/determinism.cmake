# SPDX-License-Identifier: Apache-2.0
# Every command that writes gives bit-identical outputs for any thread count
# and across runs, byte for byte: each runs with 1 thread, 2, and 2 again
# (check_deterministic.sh). Labelled `threads`: the ThreadSanitizer build runs
# these, so every threaded path (table and moment bakes with their writer
# thread, apply, render, fits, synthesis) runs there too.
set(DET ${CMAKE_CURRENT_SOURCE_DIR}/check_deterministic.sh)
set(DETOUT ${OUT}/determinism)

# cmfilter_determinism_case(<command name> <fixtures> <args>...)
function(cmfilter_determinism_case name fixtures)
  add_test(NAME cli.determinism.${name} COMMAND bash ${DET} ${DETOUT}/${name} -- ${ARGN})
  set_tests_properties(cli.determinism.${name} PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;${fixtures}"
                       LABELS "cli;threads" ENVIRONMENT "OCIO=")
endfunction()

set(T @THREADS@)
cmfilter_determinism_case(bake-colormap "" ${CMF} bake-colormap ${LUTS}/terrain.png -o @OUT@/table.exr
                          --threads ${T})
cmfilter_determinism_case(bake-colormap-tolerance "" ${CMF} bake-colormap ${LUTS}/step.png -o @OUT@/table.exr
                          --tolerance 1 --threads ${T})
cmfilter_determinism_case(bake-moments "" ${CMF} bake-moments ${FIX}/driver-37x23.png -o @OUT@/moments.exr
                          --wrap periodic --threads ${T})
cmfilter_determinism_case(bake-noise "" ${CMF} bake-noise --noise gradient:seed=3 --lod-step 1
                          --max-footprints 4096 -o @OUT@/sigma.exr --csv @OUT@/sigma.csv --threads ${T})
cmfilter_determinism_case(noise-image "" ${CMF} noise-image --noise fbm:base=gradient,octaves=3,seed=5
                          --size 64x32 -o @OUT@/noise.exr --threads ${T})
cmfilter_determinism_case(apply apply_inputs ${CMF} apply --moments ${OUT}/apply-moments.exr
                          --table ${OUT}/apply-table.exr --lod 1.5 -o @OUT@/applied.exr --threads ${T})
cmfilter_determinism_case(render "" ${CMF} render ${SC}/good.json --method gaussian -o @OUT@/render.exr
                          --threads ${T})
cmfilter_determinism_case(render-reference "" ${CMF} render ${SC}/good.json --method reference
                          -o @OUT@/render.exr --threads ${T})
cmfilter_determinism_case(make-stack "" ${CMF} make-stack ${EX}/stack-shiny-shadows.json -o @OUT@/stack.lp
                          --size 16 --spp 4 --dome fibonacci:8 --threads ${T})
cmfilter_determinism_case(fit-ptm stack_fixtures ${CMF} fit ${STF}/good.lp --model ptm-rgb -o @OUT@/fit.ptm
                          --threads ${T})
cmfilter_determinism_case(fit-lafortune stack_fixtures ${CMF} fit ${STF}/good.lp --model lafortune --lobes 2
                          -o @OUT@/fit.exr --threads ${T})
cmfilter_determinism_case(relight fit_good_ptm-rgb ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr
                          --light 0.3,0.2,0.9 -o @OUT@/relit.exr --threads ${T})
cmfilter_determinism_case(normals fit_good_ptm-rgb ${CMF} normals ${OUT}/fit-good-ptm-rgb.exr
                          -o @OUT@/normals.exr --threads ${T})
cmfilter_determinism_case(compare "" ${CMF} compare ${FIX}/cmp-a.exr ${FIX}/cmp-b.exr --heatmap @OUT@/heat.png
                          --threads ${T})
cmfilter_determinism_case(synth-analyse synth_fixtures ${CMF} synth-analyse ${OUT}/synth-fixtures/sample.png
                          -o @OUT@/analysis.exr --levels 2 --textons 64 --neighbourhood 1 --threads ${T})
cmfilter_determinism_case(synth synth_fixtures ${CMF} synth ${OUT}/synth-fixtures/sample.png -o @OUT@/map.exr
                          --size 33x21 -k 2 --levels 2 --textons 32 --neighbourhood 1 --seed 7 --threads ${T} -q)
cmfilter_determinism_case(synth-apply synth_map ${CMF} synth-apply ${OUT}/synth-map.exr
                          --source ${OUT}/synth-fixtures/sample.png --lod 1 -o @OUT@/surface.exr --threads ${T})

# Reproducible outputs: the same inputs baked in two folders give the same
# bytes, the recorded sources resolve after a move, SOURCE_DATE_EPOCH.
add_test(NAME cli.reproducible
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_reproducible.sh ${CMF} ${LUTS}/terrain.png
                 ${FIX}/driver-37x23.png ${OUT}/reproducible)
set_tests_properties(cli.reproducible PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures" LABELS cli
                     ENVIRONMENT "OCIO=")
