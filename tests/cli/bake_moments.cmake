# SPDX-License-Identifier: Apache-2.0
# bake-moments: a driver's moment pyramid (and histogram pyramid).
cmfilter_cli_case(NAME help.bake-moments EXIT 0 STDOUT "--wrap" COMMAND ${CMF} bake-moments --help)

# --- bake-moments: bad input, each with its exit code, message and no output ---
set(M ${OUT}/bad-moments.exr)
cmfilter_cli_case(NAME moments.bad.missing-file EXIT 2 STDERR "^cmfilter bake-moments: error: cannot read '.*no-such\\.exr': no such file"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/no-such.exr -o ${M})
cmfilter_cli_case(NAME moments.bad.not-an-image EXIT 3 STDERR "not-an-image\\.png' is not an image OpenImageIO can read"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/not-an-image.png -o ${M})
cmfilter_cli_case(NAME moments.bad.nan-texels EXIT 3
                  STDERR "driver-nan\\.exr' has 3 non-finite texels \\(first at \\(2, 0\\): nan\\); .*--nan zero"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/driver-nan.exr -o ${M})
cmfilter_cli_case(NAME moments.bad.multi-channel EXIT 3
                  STDERR "grid\\.png' has 3 channels \\(channels: R, G, B\\); .*--channel"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/grid.png -o ${M})
cmfilter_cli_case(NAME moments.bad.unknown-channel EXIT 3
                  STDERR "grid\\.png' has no channel 'Z' \\(channels: R, G, B\\)"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/grid.png -o ${M} --channel Z)
cmfilter_cli_case(NAME moments.bad.channel-index EXIT 3
                  STDERR "channel index 3 is outside '.*grid\\.png' \\(expected 0\\.\\.2\\)"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/grid.png -o ${M} --channel 3)
cmfilter_cli_case(NAME moments.bad.output-directory-missing EXIT 2
                  STDERR "cannot write '.*no-such-dir/m\\.exr': directory '.*no-such-dir' does not exist"
                  ABSENT ${OUT}/no-such-dir/m.exr
                  COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png -o ${OUT}/no-such-dir/m.exr)
cmfilter_cli_case(NAME moments.bad.unknown-wrap EXIT 3 STDERR "unknown wrap mode 'mirror' \\(expected black, clamp or periodic\\)"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png -o ${M} --wrap mirror)
cmfilter_cli_case(NAME moments.bad.unknown-nan-policy EXIT 3 STDERR "unknown non-finite policy 'skip'"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png -o ${M} --nan skip)
cmfilter_cli_case(NAME moments.bad.order EXIT 3 STDERR "--order is 3 \\(expected 2 or 4\\)"
                  ABSENT ${M} COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png -o ${M} --order 3)
cmfilter_cli_case(NAME moments.bad.info-missing EXIT 2 STDERR "cannot read '.*no-such-moments\\.exr': no such file"
                  COMMAND ${CMF} info ${FIX}/no-such-moments.exr)

# --- bake-moments: real pyramids -----------------------------------------------
cmfilter_cli_case(NAME moments.bake-png EXIT 0
                  STDOUT "wrote .*driver-37x23\\.exr: moment pyramid, 37 x 23, 6 levels"
                  COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png -o ${OUT}/driver-37x23.exr --wrap periodic)
set_tests_properties(cli.moments.bake-png PROPERTIES FIXTURES_SETUP moments_png)
cmfilter_cli_case(NAME moments.bake-nan-zero EXIT 0 STDOUT "non-finite 3 texels replaced by 0"
                  COMMAND ${CMF} bake-moments ${FIX}/driver-nan.exr -o ${OUT}/driver-nan.exr --nan zero)
cmfilter_cli_case(NAME moments.bake-channel EXIT 0 STDOUT "channel G, uint8"
                  COMMAND ${CMF} bake-moments ${FIX}/grid.png -o ${OUT}/grid-g.exr --channel G)
cmfilter_cli_case(NAME moments.bake-histograms EXIT 0
                  STDOUT "histograms .*driver-37x23-h\\.exr: 256 distinct values"
                  COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png -o ${OUT}/driver-37x23-m.exr
                          --histograms ${OUT}/driver-37x23-h.exr)
set_tests_properties(cli.moments.bake-histograms PROPERTIES FIXTURES_SETUP histograms_png)
cmfilter_cli_case(NAME moments.histograms-info EXIT 0 STDOUT "^  bins +256$"
                  COMMAND ${CMF} info ${OUT}/driver-37x23-h.exr)
set_tests_properties(cli.moments.histograms-info PROPERTIES FIXTURES_REQUIRED "cli_dirs;histograms_png")
cmfilter_cli_case(NAME moments.bad.too-many-values EXIT 3
                  STDERR "apply-driver\\.exr' has [0-9]+ distinct values; a histogram pyramid holds at most 256"
                  ABSENT ${OUT}/many-m.exr ${OUT}/many-h.exr
                  COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr -o ${OUT}/many-m.exr --histograms ${OUT}/many-h.exr)
add_test(NAME cli.moments.bake-quiet
         COMMAND bash -c "test -z \"$($0 bake-moments $1 -o $2 --channel 1 -q 2>&1)\" && test -f $2"
                 ${CMF} ${FIX}/grid.png ${OUT}/grid-1.exr)
set_tests_properties(cli.moments.bake-quiet PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures" LABELS cli)
cmfilter_cli_case(NAME moments.info EXIT 0 STDOUT "moment-pyramid"
                  COMMAND ${CMF} info ${OUT}/driver-37x23.exr)
set_tests_properties(cli.moments.info PROPERTIES FIXTURES_REQUIRED "cli_dirs;moments_png")
add_test(NAME cli.moments.oiiotool-info COMMAND ${OIIOTOOL} --info -v ${OUT}/driver-37x23.exr)
set_tests_properties(cli.moments.oiiotool-info PROPERTIES FIXTURES_REQUIRED moments_png LABELS cli
    PASS_REGULAR_EXPRESSION "MIP-map levels: 37x23 18x11 9x5 4x2 2x1 1x1.*wrapmodes: \"periodic,periodic\".*cmfilter:kind: \"moment-pyramid\"")
add_test(NAME cli.moments.source-sha256
         COMMAND bash -c "test \"$($0 info --json $1 | grep -o '\"source_sha256\": \"[0-9a-f]*' | grep -o '[0-9a-f]*$')\" = \"$(sha256sum $2 | cut -d' ' -f1)\""
                 ${CMF} ${OUT}/driver-37x23.exr ${FIX}/driver-37x23.png)
set_tests_properties(cli.moments.source-sha256 PROPERTIES FIXTURES_REQUIRED moments_png LABELS cli)
