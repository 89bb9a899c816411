# SPDX-License-Identifier: Apache-2.0
# bake-colormap: a colour map's Gaussian colour table, checked independently.
cmfilter_cli_case(NAME help.bake-colormap EXIT 0 STDOUT "--sigma-spacing" COMMAND ${CMF} bake-colormap --help)

# --- bake-colormap: bad input, each with its exit code, message and no output --
set(T ${OUT}/bad.exr)
cmfilter_cli_case(NAME bad.missing-file EXIT 2 STDERR "cannot read '.*no-such\\.png': no such file"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/no-such.png -o ${T})
cmfilter_cli_case(NAME bad.unreadable-file EXIT 2 STDERR "cannot read '.*fixtures': it is a directory"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX} -o ${T})
cmfilter_cli_case(NAME bad.not-an-image EXIT 3 STDERR "not-an-image\\.png' is not an image OpenImageIO can read"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/not-an-image.png -o ${T})
cmfilter_cli_case(NAME bad.zero-sized EXIT 3 STDERR "empty\\.png' is empty \\(0 bytes\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/empty.png -o ${T})
cmfilter_cli_case(NAME bad.nan-texel EXIT 3 STDERR "nan\\.exr' has a non-finite texel at \\(1, 0\\) channel 0: nan"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/nan.exr -o ${T})
cmfilter_cli_case(NAME bad.inf-texel EXIT 3 STDERR "inf\\.exr' has a non-finite texel at \\(2, 0\\) channel 2: inf"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/inf.exr -o ${T})
cmfilter_cli_case(NAME bad.sigma-max-zero EXIT 3 STDERR "--sigma-max 0 is invalid \\(expected a finite value > 0\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --sigma-max 0)
cmfilter_cli_case(NAME bad.sigma-max-negative EXIT 3 STDERR "--sigma-max -0.5 is invalid"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --sigma-max=-0.5)
cmfilter_cli_case(NAME bad.one-value EXIT 3 STDERR "--values 1 is out of range \\(expected 2\\.\\.65536"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --values 1)
cmfilter_cli_case(NAME bad.one-sigma EXIT 3 STDERR "--sigmas 1 is out of range"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --sigmas 1)
cmfilter_cli_case(NAME bad.empty-domain EXIT 3 STDERR "--domain '1:0' is empty \\(expected MIN < MAX\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --domain 1:0)
cmfilter_cli_case(NAME bad.equal-domain EXIT 3 STDERR "--domain '0.5:0.5' is empty"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --domain 0.5:0.5)
cmfilter_cli_case(NAME bad.malformed-domain EXIT 3 STDERR "--domain 'zero:1' is not a range"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --domain zero:1)
cmfilter_cli_case(NAME bad.unknown-colorspace EXIT 3
                  STDERR "unknown colour space 'bogus'.*known colour spaces:"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --colorspace bogus)
cmfilter_cli_case(NAME bad.unknown-colorspace-lists-names EXIT 3 STDERR "ACEScg"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --colorspace bogus)
cmfilter_cli_case(NAME bad.output-directory-missing EXIT 2
                  STDERR "cannot write '.*no-such-dir/t\\.exr': directory '.*no-such-dir' does not exist"
                  ABSENT ${OUT}/no-such-dir/t.exr
                  COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${OUT}/no-such-dir/t.exr)
cmfilter_cli_case(NAME bad.output-extension EXIT 3 STDERR "output '.*t\\.png' has the wrong extension \\(expected a \\.exr file\\)"
                  ABSENT ${OUT}/t.png COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${OUT}/t.png)
cmfilter_cli_case(NAME bad.unknown-wrap EXIT 3 STDERR "unknown wrap mode 'wrap'"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --wrap wrap)
cmfilter_cli_case(NAME bad.grid-needs-row EXIT 3 STDERR "grid\\.png' is 4 x 3; pass --row N or --column N"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/grid.png -o ${T})
cmfilter_cli_case(NAME bad.row-outside EXIT 3 STDERR "--row 3 is outside '.*grid\\.png' \\(expected 0\\.\\.2\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${FIX}/grid.png -o ${T} --row 3)
# --tolerance and --for: bad values, files missing or of the wrong kind.
cmfilter_cli_case(NAME bad.tolerance-zero EXIT 3 STDERR "--tolerance 0 is invalid \\(expected a CIEDE2000 difference > 0\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --tolerance 0)
cmfilter_cli_case(NAME bad.tolerance-negative EXIT 3 STDERR "--tolerance -1 is invalid \\(expected a CIEDE2000 difference > 0\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --tolerance=-1)
cmfilter_cli_case(NAME bad.tolerance-percentile EXIT 3
                  STDERR "--tolerance-percentile 0 is invalid \\(expected 0 < P <= 100; 100 is the maximum\\)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --tolerance 1 --tolerance-percentile 0)
cmfilter_cli_case(NAME bad.tolerance-impossible EXIT 3
                  STDERR "no table up to 4096 values x 1024 sigmas meets the tolerance 1e-06 \\(CIEDE2000 p99\\.9 at 20000 random \\(v, sigma\\), sigma_max 0\\.25\\): the lowest p99\\.9 reached is [0-9.e-]+, by [0-9]+ x [0-9]+ (sqrt|linear)"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/step.png -o ${T} --tolerance 1e-6 --threads 2)
cmfilter_cli_case(NAME usage.tolerance-with-values EXIT 1 STDERR "--values excludes --tolerance"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --tolerance 1 --values 64)
cmfilter_cli_case(NAME usage.tolerance-percentile-alone EXIT 1 STDERR "--tolerance-percentile requires --tolerance"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --tolerance-percentile 99)
cmfilter_cli_case(NAME usage.for-with-sigma-max EXIT 1 STDERR "--sigma-max excludes --for"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --for ${EX}/fbm-gradient-6.exr --sigma-max 1)
cmfilter_cli_case(NAME bad.for-missing EXIT 2 STDERR "cannot read '.*no-such-sigma\\.exr': no such file"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --for ${FIX}/no-such-sigma.exr)
cmfilter_cli_case(NAME bad.for-missing-scene EXIT 2 STDERR "no-such-scene\\.json: cannot read the scene: no such file"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --for ${FIX}/no-such-scene.json)
cmfilter_cli_case(NAME bad.for-plain-image EXIT 3
                  STDERR "step\\.png' is not a driver to take sigma from \\(it has no cmfilter:kind; expected a noise sigma table"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --for ${LUTS}/step.png)
cmfilter_cli_case(NAME bad.for-colour-table EXIT 3
                  STDERR "terrain\\.exr' is not a driver to take sigma from \\(cmfilter:kind is 'gaussian-color-table'; expected"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T} --for ${OUT}/terrain.exr)
set_tests_properties(cli.bad.for-colour-table PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;table_terrain")
cmfilter_cli_case(NAME bad.for-bad-scene EXIT 3 STDERR "/surfaces/0/material/driver/sigma_table: .*no-such-table\\.exr"
                  ABSENT ${T} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${T}
                                      --for ${SC}/missing-file.json)

# --- bake-colormap: real tables, checked independently -------------------------
foreach(map terrain stripes step narrow-band)
  cmfilter_cli_case(NAME bake.${map} EXIT 0 STDOUT "wrote .*${map}\\.exr: gaussian colour table, 256 values x 256 sigmas"
                    COMMAND ${CMF} bake-colormap ${LUTS}/${map}.png -o ${OUT}/${map}.exr)
  add_test(NAME cli.verify.${map} COMMAND cmfilter_verify_table ${OUT}/${map}.exr ${LUTS}/${map}.png srgb)
  set_tests_properties(cli.bake.${map} PROPERTIES FIXTURES_SETUP table_${map})
  set_tests_properties(cli.verify.${map} PROPERTIES FIXTURES_REQUIRED table_${map} LABELS cli)
endforeach()
# Periodic wraps, linear spacing, a non-default domain and table size.
foreach(wrap repeat mirror)
  cmfilter_cli_case(NAME bake.stripes-${wrap} EXIT 0 STDOUT "wrap ${wrap}"
                    COMMAND ${CMF} bake-colormap ${LUTS}/stripes.png -o ${OUT}/stripes-${wrap}.exr
                            --wrap ${wrap} --domain=-2:3 --sigma-max 2 --values 300 --sigmas 40 --sigma-spacing linear)
  add_test(NAME cli.verify.stripes-${wrap}
           COMMAND cmfilter_verify_table ${OUT}/stripes-${wrap}.exr ${LUTS}/stripes.png srgb)
  set_tests_properties(cli.bake.stripes-${wrap} PROPERTIES FIXTURES_SETUP table_stripes_${wrap})
  set_tests_properties(cli.verify.stripes-${wrap} PROPERTIES FIXTURES_REQUIRED table_stripes_${wrap} LABELS cli)
endforeach()
# A non-sRGB input space: a hard-coded sRGB curve cannot pass this one.
cmfilter_cli_case(NAME bake.gamma22 EXIT 0 STDOUT "Gamma 2\\.2 Rec\\.709 -> Linear Rec\\.709 \\(--colorspace\\)"
                  COMMAND ${CMF} bake-colormap ${FIX}/ramp.png -o ${OUT}/ramp-g22.exr --colorspace g22_rec709)
add_test(NAME cli.verify.gamma22 COMMAND cmfilter_verify_table ${OUT}/ramp-g22.exr ${FIX}/ramp.png gamma2.2)
set_tests_properties(cli.bake.gamma22 PROPERTIES FIXTURES_SETUP table_g22)
set_tests_properties(cli.verify.gamma22 PROPERTIES FIXTURES_REQUIRED "table_g22;cli_fixtures" LABELS cli)
# The file's own colour-space metadata (a gAMA chunk: gamma 2.2), no --colorspace.
cmfilter_cli_case(NAME bake.gamma22-from-file EXIT 0
                  STDOUT "Gamma 2\\.2 Rec\\.709 -> Linear Rec\\.709 \\(file metadata \\(gamma 2\\.2\\)\\)"
                  COMMAND ${CMF} bake-colormap ${FIX}/ramp-gamma22.png -o ${OUT}/ramp-gamma22.exr)
add_test(NAME cli.verify.gamma22-from-file
         COMMAND cmfilter_verify_table ${OUT}/ramp-gamma22.exr ${FIX}/ramp-gamma22.png gamma2.2)
set_tests_properties(cli.bake.gamma22-from-file PROPERTIES FIXTURES_SETUP table_g22_file)
set_tests_properties(cli.verify.gamma22-from-file PROPERTIES FIXTURES_REQUIRED "table_g22_file;cli_fixtures" LABELS cli)
# A row of a larger image.
cmfilter_cli_case(NAME bake.grid-row EXIT 0 STDOUT "grid\\.png \\(4 x 3, row 2\\)"
                  COMMAND ${CMF} bake-colormap ${FIX}/grid.png -o ${OUT}/grid-row.exr --row 2 --values 16 --sigmas 4)

# The smallest table for a tolerance, and sigma_max from what the table is for.
cmfilter_cli_case(NAME tolerance.terrain EXIT 0
                  STDOUT "size     chose [0-9]+ values x [0-9]+ sigmas \\((sqrt|linear)\\): [0-9]+ bytes, [0-9.]+% of the default 256 x 256 \\(786432 bytes\\)"
                  COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${OUT}/tolerance-terrain.exr --domain=-0.68:0.68
                          --tolerance 1 --threads 2)
set_tests_properties(cli.tolerance.terrain PROPERTIES FIXTURES_SETUP table_tolerance)
add_test(NAME cli.tolerance.verify COMMAND cmfilter_verify_table ${OUT}/tolerance-terrain.exr ${LUTS}/terrain.png srgb)
set_tests_properties(cli.tolerance.verify PROPERTIES FIXTURES_REQUIRED table_tolerance LABELS cli)
cmfilter_cli_case(NAME tolerance.for-sigma-table EXIT 0
                  STDOUT "sigmas   0 \\.\\. 0\\.2448[0-9]*, (sqrt|linear) spacing; sigma_max: --for: the largest box sigma of the noise sigma table"
                  COMMAND ${CMF} bake-colormap ${LUTS}/step.png -o ${OUT}/tolerance-step.exr --domain=-0.68:0.68
                          --for ${EX}/fbm-gradient-6.exr --tolerance 2 --threads 2)
cmfilter_cli_case(NAME for-scene EXIT 0
                  STDOUT "sigma_max: --for: scene '.*plane-fbm-terrain\\.json', surface 0: the largest box sigma"
                  COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${OUT}/for-scene.exr --domain=-0.68:0.68
                          --for ${EX}/plane-fbm-terrain.json --values 64 --sigmas 16)
cmfilter_cli_case(NAME for-scene-image-driver EXIT 0
                  STDOUT "surface 0: the largest sigma over the aligned 2\\^k blocks of the driver image '.*noise-driver\\.png'"
                  COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${OUT}/for-scene-image.exr --domain=-0.68:0.68
                          --for ${SC}/texture-driver.json --values 64 --sigmas 16)

# The table opens in OpenImageIO's own tools, metadata and all.
add_test(NAME cli.oiiotool-info COMMAND ${OIIOTOOL} --info -v ${OUT}/terrain.exr)
set_tests_properties(cli.oiiotool-info PROPERTIES FIXTURES_REQUIRED table_terrain LABELS cli
    PASS_REGULAR_EXPRESSION "cmfilter:kind: \"gaussian-color-table\"")
