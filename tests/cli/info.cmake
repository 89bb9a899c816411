# SPDX-License-Identifier: Apache-2.0
# info: what a cmfilter artefact holds. The artefacts of bake-moments, apply,
# noise-image and bake-noise are read back in those commands' files.
cmfilter_cli_case(NAME help.info EXIT 0 STDOUT "FILE" COMMAND ${CMF} info --help)

# --- info: bad input -----------------------------------------------------------
cmfilter_cli_case(NAME bad.info-not-artefact EXIT 3 STDERR "terrain\\.png' is an image but not a cmfilter artefact"
                  COMMAND ${CMF} info ${LUTS}/terrain.png)
cmfilter_cli_case(NAME bad.info-missing EXIT 2 STDERR "cannot read '.*no-such\\.exr': no such file"
                  COMMAND ${CMF} info ${FIX}/no-such.exr)

# --- info: colour tables baked by bake-colormap --------------------------------
cmfilter_cli_case(NAME info.tolerance EXIT 0 STDOUT "tolerance_statistic +p99\\.9"
                  COMMAND ${CMF} info ${OUT}/tolerance-terrain.exr)
set_tests_properties(cli.info.tolerance PROPERTIES FIXTURES_REQUIRED "cli_dirs;table_tolerance")
cmfilter_cli_case(NAME info.table EXIT 0
                  STDOUT "gaussian-color-table"
                  COMMAND ${CMF} info ${OUT}/terrain.exr)
set_tests_properties(cli.info.table PROPERTIES FIXTURES_REQUIRED "cli_dirs;table_terrain")
cmfilter_cli_case(NAME info.table-parameters EXIT 0
                  STDOUT "source_sha256 +[0-9a-f]{64}"
                  COMMAND ${CMF} info ${OUT}/terrain.exr)
set_tests_properties(cli.info.table-parameters PROPERTIES FIXTURES_REQUIRED "cli_dirs;table_terrain")
# The recorded source hash is the file's SHA-256, as sha256sum computes it.
add_test(NAME cli.info.source-sha256
         COMMAND bash -c "test \"$($0 info --json $1 | grep -o '\"source_sha256\": \"[0-9a-f]*' | grep -o '[0-9a-f]*$')\" = \"$(sha256sum $2 | cut -d' ' -f1)\""
                 ${CMF} ${OUT}/terrain.exr ${LUTS}/terrain.png)
set_tests_properties(cli.info.source-sha256 PROPERTIES FIXTURES_REQUIRED table_terrain LABELS cli)
