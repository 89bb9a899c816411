# SPDX-License-Identifier: Apache-2.0
# Every command's --json summary against the schema file users validate with
# (docs/cmfilter.schema.json, docs/json-schema.md), each variant that adds or
# leaves out fields (check_json_schema.py also checks the schema refuses an
# undocumented field and a number given as text). python3-jsonschema: the
# system Python's (bootstrap.sh installs it).
find_program(CMFILTER_SYSTEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT CMFILTER_SYSTEM_PYTHON)
  find_program(CMFILTER_SYSTEM_PYTHON python3 REQUIRED)
endif()
set(SCHEMA ${PROJECT_SOURCE_DIR}/docs/cmfilter.schema.json)
set(JOUT ${OUT}/json-schema)
add_test(NAME cli.json-schema.setup COMMAND ${CMAKE_COMMAND} -E make_directory ${JOUT})
set_tests_properties(cli.json-schema.setup PROPERTIES FIXTURES_SETUP json_dir FIXTURES_REQUIRED cli_dirs LABELS cli)

# cmfilter_json_case(<name> <fixtures> <args>...): `cmfilter <args> --json`.
function(cmfilter_json_case name fixtures)
  add_test(NAME cli.json-schema.${name}
           COMMAND ${CMFILTER_SYSTEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_json_schema.py ${SCHEMA} -- ${ARGN}
                   --json)
  set_tests_properties(cli.json-schema.${name} PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;json_dir;${fixtures}"
                       LABELS cli ENVIRONMENT "OCIO=")
endfunction()

cmfilter_json_case(bake-colormap "" ${CMF} bake-colormap ${LUTS}/terrain.png -o ${JOUT}/table.exr -d half)
cmfilter_json_case(bake-colormap-tolerance "" ${CMF} bake-colormap ${LUTS}/step.png -o ${JOUT}/table-tol.exr
                   --tolerance 2 --error-samples 0)
cmfilter_json_case(bake-moments apply_inputs ${CMF} bake-moments ${FIX}/driver-4values.png -o ${JOUT}/moments.exr
                   --histograms ${JOUT}/histograms.exr --tile 32 32 --tolerance 100 --table ${OUT}/apply-table.exr
                   --measure-lods 1)
cmfilter_json_case(bake-moments-color-pyramid apply_inputs ${CMF} bake-moments ${FIX}/driver-4values.png
                   -o ${JOUT}/color-pyramid.exr --method color-pyramid --table ${OUT}/apply-table.exr -d half)
cmfilter_json_case(bake-moments-tolerance-color-pyramid apply_inputs ${CMF} bake-moments ${FIX}/apply-driver.exr
                   -o ${JOUT}/tolerance-cp.exr --tolerance 0.05 --table ${OUT}/apply-table.exr --measure-lods 1,2)
cmfilter_json_case(bake-moments-segments apply_inputs ${CMF} bake-moments ${FIX}/apply-driver.exr
                   -o ${JOUT}/segments.exr --segments ${OUT}/apply-table.exr --tolerance 0.5)
cmfilter_json_case(apply-segments "apply_inputs;apply_segments" ${CMF} apply --moments ${OUT}/apply-segments.exr
                   --table ${OUT}/apply-table.exr --lod 1 --method segments -o ${JOUT}/segments-applied.exr)
cmfilter_json_case(bake-noise "" ${CMF} bake-noise --noise gradient:seed=3 --lod-step 1 --max-footprints 4096
                   -o ${JOUT}/sigma.exr --csv ${JOUT}/sigma.csv)
cmfilter_json_case(noise-image "" ${CMF} noise-image --noise fbm --size 32x16 -o ${JOUT}/noise.exr)
cmfilter_json_case(apply apply_inputs ${CMF} apply --moments ${OUT}/apply-moments.exr --table ${OUT}/apply-table.exr
                   --lod 1.5 -o ${JOUT}/applied.exr)
cmfilter_json_case(apply-tolerance apply_inputs ${CMF} apply --moments ${OUT}/apply-moments.exr
                   --table ${OUT}/apply-table.exr --lod 1 --tolerance 100 --measure-lods 1 -o ${JOUT}/applied-tol.exr)
cmfilter_json_case(render "" ${CMF} render ${SC}/good.json --method gaussian -o ${JOUT}/render.exr
                   --aov ${JOUT}/render-aov)
cmfilter_json_case(render-auto "" ${CMF} render ${SCB}/texture-auto.json --method auto --tolerance 100
                   --measure-lods 1 -o ${JOUT}/render-auto.exr)
cmfilter_json_case(render-auto-noise "" ${CMF} render ${SCB}/noise-auto.json --method auto --tolerance 100
                   --measure-lods 0 -o ${JOUT}/render-auto-noise.exr)
cmfilter_json_case(render-auto-microsurface microsurface_scene ${CMF} render ${MICRO_SCENE} --method auto
                   --tolerance 1 -o ${JOUT}/render-auto-microsurface.exr)
cmfilter_json_case(render-segments "" ${CMF} render ${SC}/texture-step.json --method segments
                   -o ${JOUT}/render-segments.exr)
cmfilter_json_case(render-mixture-noise "" ${CMF} render ${SC}/good.json --method mixture --sub-footprints 2
                   -o ${JOUT}/render-mixture-noise.exr)
cmfilter_json_case(render-reference "" ${CMF} render ${SC}/good.json --method reference -o ${JOUT}/render-ref.exr)
cmfilter_json_case(compare "" ${CMF} compare ${FIX}/cmp-a.exr ${FIX}/cmp-b.exr)
cmfilter_json_case(compare-gate "" ${CMF} compare ${FIX}/cmp-a.exr ${FIX}/cmp-b.exr --heatmap ${JOUT}/heat.png
                   --gate p95 --warn 0.5 --fail 1000)
cmfilter_json_case(make-stack "" ${CMF} make-stack ${EX}/stack-shiny-shadows.json -o ${JOUT}/stack.lp --size 8
                   --spp 1 --dome fibonacci:8)
cmfilter_json_case(fit-ptm stack_fixtures ${CMF} fit ${STF}/good.lp --model ptm-rgb -o ${JOUT}/fit.ptm)
cmfilter_json_case(fit-held-out stack_fixtures ${CMF} fit ${STF}/good.lp --model hsh2 -o ${JOUT}/fit.exr
                   --held-out ${STF}/good.lp)
cmfilter_json_case(fit-lafortune stack_fixtures ${CMF} fit ${STF}/good.lp --model lafortune --lobes 1
                   -o ${JOUT}/fit-lafortune.exr)
cmfilter_json_case(relight fit_good_ptm-rgb ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr --light 0.3,0.2,0.9
                   -o ${JOUT}/relit.exr)
cmfilter_json_case(relight-reference "fit_good_ptm-rgb;stack_fixtures" ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr
                   --reference ${STF}/good.lp)
cmfilter_json_case(normals fit_good_ptm-rgb ${CMF} normals ${OUT}/fit-good-ptm-rgb.exr -o ${JOUT}/normals.exr)
cmfilter_json_case(normals-reference "bundled_stacks;bundled_fit" ${CMF} normals ${BUNDLED}/nd-hsh3.exr
                   --reference ${BUNDLED}/near-diffuse/stack.normals.exr)
cmfilter_json_case(info-table table_terrain ${CMF} info ${OUT}/terrain.exr)
cmfilter_json_case(info-stack stack_fixtures ${CMF} info ${STF}/good.lp)
cmfilter_json_case(info-map synth_map ${CMF} info ${OUT}/synth-map.exr)
cmfilter_json_case(synth-analyse synth_fixtures ${CMF} synth-analyse ${OUT}/synth-fixtures/sample.png
                   -o ${JOUT}/analysis.exr --levels 2 --textons 32 --neighbourhood 1)
cmfilter_json_case(synth synth_fixtures ${CMF} synth ${OUT}/synth-fixtures/sample.png -o ${JOUT}/map.exr
                   --size 33x21 -k 2 --levels 2 --textons 32 --neighbourhood 1 --quality
                   --preview ${JOUT}/preview.png)
cmfilter_json_case(synth-apply synth_map ${CMF} synth-apply ${OUT}/synth-map.exr
                   --source ${OUT}/synth-fixtures/sample.png --lod 1 -o ${JOUT}/surface.exr)
