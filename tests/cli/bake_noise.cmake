# SPDX-License-Identifier: Apache-2.0
# bake-noise: a noise's sigma table per LOD.
cmfilter_cli_case(NAME help.bake-noise EXIT 0 STDOUT "--lod-step" COMMAND ${CMF} bake-noise --help)

cmfilter_cli_case(NAME bake-noise.write EXIT 0 STDOUT "noise sigma table, 7 LODs from -4 in steps of 1"
                  COMMAND ${CMF} bake-noise --noise gradient:seed=3 --lod-step 1 --max-footprints 4096
                          -o ${OUT}/sigma.exr --csv ${OUT}/sigma.csv)
set_tests_properties(cli.bake-noise.write PROPERTIES FIXTURES_SETUP noise_sigma)
cmfilter_cli_case(NAME bake-noise.info EXIT 0 STDOUT "noise sigma table \\(Heitz et al"
                  COMMAND ${CMF} info ${OUT}/sigma.exr)
set_tests_properties(cli.bake-noise.info PROPERTIES FIXTURES_REQUIRED "cli_dirs;noise_sigma")
add_test(NAME cli.bake-noise.csv-header COMMAND head -1 ${OUT}/sigma.csv)
set_tests_properties(cli.bake-noise.csv-header PROPERTIES FIXTURES_REQUIRED noise_sigma LABELS cli
    PASS_REGULAR_EXPRESSION "^lod,width,box_sigma,box_ci,box_footprints")
cmfilter_cli_case(NAME bake-noise.json EXIT 0 STDOUT "\"kind\": \"noise-sigma-table\""
                  COMMAND ${CMF} bake-noise --noise value:seed=1 --lod-step 2 --max-footprints 1024 --json
                          -o ${OUT}/sigma-json.exr)
set(NS ${OUT}/bad-sigma.exr)
cmfilter_cli_case(NAME bake-noise.bad.spec EXIT 3 STDERR "noise kind 'simplex' is unknown \\(expected gradient \\(or perlin"
                  ABSENT ${NS} COMMAND ${CMF} bake-noise --noise simplex -o ${NS})
# "perlin", as users and OSL call gradient noise: the same table as
# gradient (its CSV byte for byte), recorded as gradient.
add_test(NAME cli.bake-noise.perlin-is-gradient
         COMMAND bash -c "'${CMF}' bake-noise --noise perlin:seed=3 --lod-step 1 --max-footprints 4096 -q -o '${OUT}/perlin.exr' --csv '${OUT}/perlin.csv' && cmp '${OUT}/perlin.csv' '${OUT}/sigma.csv' && '${CMF}' info '${OUT}/perlin.exr' | grep -F 'gradient:seed=3'")
set_tests_properties(cli.bake-noise.perlin-is-gradient PROPERTIES FIXTURES_REQUIRED "cli_dirs;noise_sigma" LABELS cli)
cmfilter_cli_case(NAME bake-noise.bad.spec-range EXIT 3 STDERR "lacunarity"
                  ABSENT ${NS} COMMAND ${CMF} bake-noise --noise fbm:lacunarity=0.5 -o ${NS})
cmfilter_cli_case(NAME bake-noise.bad.output-directory-missing EXIT 2
                  STDERR "cannot write '.*no-such-dir/s\\.exr': directory '.*no-such-dir' does not exist"
                  ABSENT ${OUT}/no-such-dir/s.exr
                  COMMAND ${CMF} bake-noise --noise gradient -o ${OUT}/no-such-dir/s.exr)
cmfilter_cli_case(NAME bake-noise.bad.lod-step EXIT 3 STDERR "--lod-step 0\\.0+ is invalid"
                  ABSENT ${NS} COMMAND ${CMF} bake-noise --noise gradient --lod-step 0 -o ${NS})
cmfilter_cli_case(NAME bake-noise.bad.lod-step-negative EXIT 3 STDERR "--lod-step -0\\.250* is invalid"
                  ABSENT ${NS} COMMAND ${CMF} bake-noise --noise gradient --lod-step=-0.25 -o ${NS})
cmfilter_cli_case(NAME bake-noise.bad.csv-directory-missing EXIT 2 STDERR "no-such-dir"
                  ABSENT ${NS} COMMAND ${CMF} bake-noise --noise gradient -o ${NS} --csv ${OUT}/no-such-dir/s.csv)
