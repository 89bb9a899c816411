# SPDX-License-Identifier: Apache-2.0
# apply: a driver's moments filtered through a colour table into an image. Its
# inputs are baked by cli.apply.setup (CMakeLists.txt), fixture apply_inputs.

# cmfilter_apply_case(NAME ... EXIT ... [STDERR ...] [STDOUT ...] [ABSENT ...] COMMAND args after "apply")
function(cmfilter_apply_case)
  cmake_parse_arguments(A "" "NAME" "" ${ARGN})
  cmfilter_cli_case(NAME apply.${A_NAME} ${A_UNPARSED_ARGUMENTS})
  set_tests_properties(cli.apply.${A_NAME} PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs")
endfunction()
cmfilter_cli_case(NAME help.apply EXIT 0 STDOUT "--histograms" COMMAND ${CMF} apply --help)

# --- apply: bad input, each with its exit code, message and no output ----------
set(A ${OUT}/bad-apply.exr)
cmfilter_apply_case(NAME bad.not-moments EXIT 3
                    STDERR "^cmfilter apply: error: '.*apply-table\\.exr' is not a cmfilter moment pyramid \\(cmfilter:kind is 'gaussian-color-table', expected 'moment-pyramid'\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AT} --table ${AT} --lod 0 -o ${A})
cmfilter_apply_case(NAME bad.moments-not-an-image EXIT 3 STDERR "not-an-image\\.png' is not an image OpenImageIO can read"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${FIX}/not-an-image.png --table ${AT} --lod 0 -o ${A})
cmfilter_apply_case(NAME bad.moments-missing EXIT 2 STDERR "cannot read '.*no-such-moments\\.exr': no such file"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${FIX}/no-such-moments.exr --table ${AT} --lod 0 -o ${A})
cmfilter_apply_case(NAME bad.not-a-table EXIT 3
                    STDERR "apply-moments\\.exr' is not a cmfilter colour table \\(cmfilter:kind is 'moment-pyramid', expected 'gaussian-color-table'\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AM} --lod 0 -o ${A})
cmfilter_apply_case(NAME bad.domain-no-overlap EXIT 3
                    STDERR "the driver range \\[5, 5\\.9375\\] of '.*apply-far-moments\\.exr' does not overlap the domain \\[0, 1\\] of table '.*apply-table\\.exr'"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${OUT}/apply-far-moments.exr --table ${AT} --lod 0 -o ${A})
cmfilter_apply_case(NAME bad.driver-missing EXIT 2
                    STDERR "cannot read driver '[^']*apply-gone-driver\\.exr' recorded in '.*apply-gone-moments\\.exr' \\(cmfilter:source\\): no such file; pass --driver PATH"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${OUT}/apply-gone-moments.exr --table ${AT} --lod 0
                                        --method reference -o ${A})
cmfilter_apply_case(NAME bad.map-missing EXIT 2
                    STDERR "cannot read colour map '[^']*apply-gone-map\\.exr' recorded in '.*apply-gone-table\\.exr' \\(cmfilter:source\\): no such file; pass --map PATH"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${OUT}/apply-gone-table.exr --lod 0
                                        --method naive -o ${A})
cmfilter_apply_case(NAME bad.map-override-missing EXIT 2 STDERR "cannot read '.*no-such\\.exr': no such file"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 0 --method naive
                                        --map ${FIX}/no-such.exr -o ${A})
cmfilter_apply_case(NAME bad.output-directory-missing EXIT 2
                    STDERR "cannot write '.*no-such-dir/a\\.exr': directory '.*no-such-dir' does not exist"
                    ABSENT ${OUT}/no-such-dir/a.exr
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 0 -o ${OUT}/no-such-dir/a.exr)
cmfilter_apply_case(NAME bad.output-extension EXIT 3
                    STDERR "output '.*a\\.tif' has the wrong extension \\(expected \\.exr, \\.png, \\.jpg or \\.jpeg\\)"
                    ABSENT ${OUT}/a.tif COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 0 -o ${OUT}/a.tif)
foreach(size 0x4 12 4x-3 axb)
  cmfilter_apply_case(NAME bad.size-${size} EXIT 3
                      STDERR "--size '${size}' is not a size \\(expected WxH, two integers 1\\.\\.65536\\)"
                      ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 0 --size ${size} -o ${A})
endforeach()
cmfilter_apply_case(NAME bad.unknown-method EXIT 3
                    STDERR "unknown method 'box' \\(expected naive, gaussian, mixture, exact, color-pyramid, segments or reference\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 0 --method box -o ${A})
cmfilter_apply_case(NAME bad.exact-without-histograms EXIT 3
                    STDERR "--method exact needs --histograms H\\.exr"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 0 --method exact -o ${A})
cmfilter_apply_case(NAME bad.mixture-two-moments EXIT 3
                    STDERR "--method mixture needs a moment pyramid of order 4; '.*apply-moments\\.exr' holds 2 moments \\(re-bake it with bake-moments --order 4\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --method mixture -o ${A})
cmfilter_apply_case(NAME bad.tolerance-none-meets EXIT 3
                    STDERR "'.*apply-moments\\.exr' through '.*apply-table\\.exr': no method meets --tolerance 1e-09 \\(mean CIEDE2000 at LOD 1, 2, 3, 4, 5\\); the closest is [a-z]+ at [0-9.e-]+ \\(LOD [1-5]\\); not tried: color-pyramid: no colour pyramid of the driver through this map \\(--color-pyramid P\\.exr\\); not tried: segments: no segment pyramid of the driver \\(--segment-pyramid S\\.exr\\); not tried: mixture: '.*apply-moments\\.exr' holds 2 moments \\(mixture needs bake-moments --order 4\\); not tried: exact: no histogram pyramid \\(--histograms H\\.exr\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --tolerance 1e-9 -o ${A})
cmfilter_apply_case(NAME bad.tolerance-zero EXIT 3
                    STDERR "--tolerance 0 is invalid \\(expected a CIEDE2000 difference > 0\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --tolerance 0 -o ${A})
cmfilter_apply_case(NAME bad.measure-lods-negative EXIT 3
                    STDERR "--measure-lods holds -1 \\(expected finite levels of detail >= 0\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --tolerance 1
                                        --measure-lods 1,-1 -o ${A})
cmfilter_apply_case(NAME usage.tolerance-with-method EXIT 1 STDERR "--method excludes --tolerance"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --tolerance 1
                                        --method gaussian -o ${A})
# --tolerance chooses, reports every method measured and records the choice
# in the image (read back by oiiotool): a tolerance everything meets takes
# the cheapest, naive.
cmfilter_apply_case(NAME tolerance.records-choice EXIT 0
                    STDOUT "naive +4 B/texel, worst .*<- chosen.*cmfilter:method: \"naive\".*cmfilter:method_lods: \"1, 2\".*cmfilter:method_tolerance: 100"
                    COMMAND bash -c "set -o pipefail && ($0 apply --moments $1 --table $2 --lod 1 --tolerance 100 --measure-lods 1,2 -o $3 && oiiotool --info -v $3) | tr '\\n' ' '"
                            ${CMF} ${AM} ${AT} ${OUT}/apply-tolerance.exr)
cmfilter_apply_case(NAME moments.tolerance-without-table EXIT 3
                    STDERR "--tolerance needs the colour table to measure against \\(--table\\)"
                    ABSENT ${OUT}/tolerance-moments.exr COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr -o ${OUT}/tolerance-moments.exr
                                        --tolerance 1)
# In half, even the colour pyramid is off by its rounding: nothing meets 1e-9.
cmfilter_apply_case(NAME moments.tolerance-none-meets EXIT 3
                    STDERR "'.*apply-driver\\.exr' through '.*apply-table\\.exr': no method meets --tolerance 1e-09 .*the closest is color-pyramid"
                    ABSENT ${OUT}/tolerance-moments.exr
                    COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr -o ${OUT}/tolerance-moments.exr
                            --tolerance 1e-9 --table ${AT} -d half)
# The order follows the choice: two moments for naive, recorded with it.
cmfilter_apply_case(NAME moments.tolerance-records-choice EXIT 0
                    STDOUT "cmfilter:method: \"naive\".*cmfilter:method_table: \"apply-table\\.exr\".*cmfilter:moment_order: 2"
                    COMMAND bash -c "set -o pipefail && ($0 bake-moments $1 -o $2 --tolerance 100 --table $3 --measure-lods 1 -q && oiiotool --info -v $2) | tr '\\n' ' '"
                            ${CMF} ${FIX}/apply-driver.exr ${OUT}/tolerance-chosen-moments.exr ${AT})
cmfilter_apply_case(NAME usage.lod-not-a-number EXIT 1 STDERR "^cmfilter apply: error: .*--lod"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod one -o ${A})
cmfilter_apply_case(NAME usage.missing-lod EXIT 1 STDERR "^cmfilter apply: error: .*--lod is required"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} -o ${A})

# --- apply: warnings (exit 0) and outputs --------------------------------------
# The driver reaches [-0.0998, 1.0999]: 110 of its 1024 texels lie outside [0, 1].
cmfilter_apply_case(NAME warn.partial-overlap EXIT 0
                    STDERR "warning: 110 of the driver's texels \\(10\\.7421875%\\) lie outside the domain \\[0, 1\\]"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 2 -o ${OUT}/apply-partial.exr)
set_tests_properties(cli.apply.warn.partial-overlap PROPERTIES FIXTURES_SETUP apply_partial)
cmfilter_apply_case(NAME warn.lod-below EXIT 0
                    STDERR "warning: --lod -1 is outside \\[0, 5\\] for '.*apply-moments\\.exr' \\(32 x 32\\); clamped to 0"
                    STDOUT "gaussian, 32 x 32 at lod 0 \\(asked -1\\)"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod=-1 -o ${OUT}/apply-below.exr)
cmfilter_apply_case(NAME warn.lod-above EXIT 0 STDERR "warning: --lod 9\\.5 is outside \\[0, 5\\].*clamped to 5"
                    STDOUT "1 x 1 at lod 5"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 9.5 -o ${OUT}/apply-above.exr)
cmfilter_apply_case(NAME warn.map-hash EXIT 0
                    STDERR "warning: colour map '.*ramp\\.png' \\(sha256 [0-9a-f]+\\) is not the file '.*apply-table\\.exr' was baked from"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --method naive --map ${FIX}/ramp.png
                            -o ${OUT}/apply-other-map.exr)
cmfilter_apply_case(NAME driver-override EXIT 0 STDOUT "driver +.*apply-driver\\.exr"
                    COMMAND ${CMF} apply --moments ${OUT}/apply-gone-moments.exr --table ${AT} --lod 1
                            --method reference --driver ${FIX}/apply-driver.exr -o ${OUT}/apply-override.exr)
cmfilter_apply_case(NAME map-override EXIT 0 STDOUT "map +.*apply-map\\.exr"
                    COMMAND ${CMF} apply --moments ${AM} --table ${OUT}/apply-gone-table.exr --lod 1
                            --method naive --map ${FIX}/apply-map.exr -o ${OUT}/apply-map-override.exr)
cmfilter_apply_case(NAME png-size EXIT 0 STDOUT "wrote .*apply\\.png: gaussian, 20 x 12 at lod 1\\.5"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1.5 --size 20x12 -o ${OUT}/apply.png)
set_tests_properties(cli.apply.png-size PROPERTIES FIXTURES_SETUP apply_png)
add_test(NAME cli.apply.png-info COMMAND ${OIIOTOOL} --info ${OUT}/apply.png)
set_tests_properties(cli.apply.png-info PROPERTIES FIXTURES_REQUIRED apply_png LABELS cli
    PASS_REGULAR_EXPRESSION "20 x +12, 3 channel, uint8 png")
cmfilter_apply_case(NAME jpeg EXIT 0 STDOUT "wrote .*apply\\.jpg: naive, 8 x 8 at lod 2"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 2 --method naive -o ${OUT}/apply.jpg)
cmfilter_apply_case(NAME json EXIT 0 STDOUT "\"sigma_clamped\": [0-9]+"
                    COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 3 --json -o ${OUT}/apply-json.exr)
cmfilter_apply_case(NAME info EXIT 0 STDOUT "filtered-image"
                    COMMAND ${CMF} info ${OUT}/apply-partial.exr)
# apply-partial.exr comes from warn.partial-overlap: a fixture, so the test
# runs it first even when only this one is selected.
set_tests_properties(cli.apply.info PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_partial")

# --- the baked colour pyramid (--method color-pyramid) ---------------------------
set(CP ${OUT}/apply-color-pyramid.exr)
cmfilter_apply_case(NAME color-pyramid.bake EXIT 0
                    STDOUT "wrote .*apply-color-pyramid\\.exr: colour pyramid, 32 x 32, 6 levels.*map +.*apply-map\\.exr \\(digest [0-9a-f]{12}; apply refuses another\\).*12 bytes per texel"
                    COMMAND bash -c "$0 bake-moments $1 --method color-pyramid --table $2 -o $3 | tr '\\n' ' '"
                            ${CMF} ${FIX}/apply-driver.exr ${AT} ${CP})
set_tests_properties(cli.apply.color-pyramid.bake PROPERTIES FIXTURES_SETUP apply_color_pyramid)
# Applied, it is the reference (the box mean of C0(f) from the driver) within
# float rounding, at an integer and a fractional LOD.
cmfilter_apply_case(NAME color-pyramid.equals-reference EXIT 0
                    COMMAND bash -c "set -e\nfor lod in 0 2 3.5\ndo $0 apply --moments $1 --table $2 --lod $lod --method color-pyramid -o $4/cp-$lod.exr -q\n$0 apply --moments $3 --table $2 --lod $lod --method reference -o $4/ref-$lod.exr -q\noiiotool --fail 2e-6 --hardfail 2e-6 $4/cp-$lod.exr $4/ref-$lod.exr --diff > /dev/null\ndone"
                            ${CMF} ${CP} ${AT} ${AM} ${OUT})
set_tests_properties(cli.apply.color-pyramid.equals-reference PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_color_pyramid")
cmfilter_apply_case(NAME color-pyramid.info EXIT 0
                    STDOUT "colour pyramid of a driver through one colour map.*map_sha256 +[0-9a-f]{64}"
                    COMMAND bash -c "$0 info $1 | tr '\\n' ' '" ${CMF} ${CP})
set_tests_properties(cli.apply.color-pyramid.info PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_color_pyramid")
# Another map (the ramp, through --map): refused, no image.
cmfilter_apply_case(NAME bad.color-pyramid-other-map EXIT 3
                    STDERR "colour pyramid '.*apply-color-pyramid\\.exr' was baked through another colour map \\('.*apply-map\\.exr'\\) than the map of table '.*apply-table\\.exr' \\('.*ramp\\.png'\\): its colours or wrap differ"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${CP} --table ${AT} --map ${FIX}/ramp.png --lod 1
                                        --method color-pyramid -o ${A})
set_tests_properties(cli.apply.bad.color-pyramid-other-map PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_color_pyramid")
cmfilter_apply_case(NAME bad.color-pyramid-of-moments EXIT 3
                    STDERR "--method color-pyramid reads a colour pyramid, and '.*apply-moments\\.exr' is a moment pyramid \\(bake one with bake-moments DRIVER --method color-pyramid --table T\\.exr\\)"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --method color-pyramid -o ${A})
cmfilter_apply_case(NAME bad.color-pyramid-without-table EXIT 3
                    STDERR "--method color-pyramid bakes C0\\(f\\) through a colour map: give its table with --table"
                    ABSENT ${OUT}/cp-none.exr
                    COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr --method color-pyramid -o ${OUT}/cp-none.exr)
cmfilter_apply_case(NAME bad.bake-method-exact EXIT 3
                    STDERR "--method exact reads no baked pyramid of its own"
                    ABSENT ${OUT}/cp-none.exr
                    COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr --method exact -o ${OUT}/cp-none.exr)
# --tolerance with --color-pyramid: on this driver through the hard-edged map
# nothing cheaper meets 0.05 at LOD 1-3 (gaussian and naive are 1 and more
# off), the colour pyramid does, and apply reads it.
cmfilter_apply_case(NAME color-pyramid.tolerance EXIT 0
                    STDOUT "color-pyramid +12 B/texel, worst +0 \\(LOD 1\\).*<- chosen.*cmfilter:method: \"color-pyramid\""
                    COMMAND bash -c "set -o pipefail && ($0 apply --moments $1 --table $2 --color-pyramid $3 --lod 1 --tolerance 0.05 --measure-lods 1,2,3 -o $4 && oiiotool --info -v $4) | tr '\\n' ' '"
                            ${CMF} ${AM} ${AT} ${CP} ${OUT}/apply-cp-tolerance.exr)
set_tests_properties(cli.apply.color-pyramid.tolerance PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_color_pyramid")
# bake-moments --tolerance measures the colour pyramid too and writes it
# when it is the cheapest that meets.
cmfilter_apply_case(NAME moments.tolerance-color-pyramid EXIT 0
                    STDOUT "cmfilter:kind: \"color-pyramid\".*cmfilter:method: \"color-pyramid\""
                    COMMAND bash -c "set -o pipefail && ($0 bake-moments $1 -o $2 --tolerance 0.05 --table $3 --measure-lods 1,2,3 -q && oiiotool --info -v $2) | tr '\\n' ' '"
                            ${CMF} ${FIX}/apply-driver.exr ${OUT}/tolerance-chosen-cp.exr ${AT})

# The done-when check: reference against oiiotool --colormap + maketx --filter box.
find_program(MAKETX_CLI maketx)
if(MAKETX_CLI)
  add_test(NAME cli.apply.reference-vs-oiiotool-maketx
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_apply_vs_oiiotool.sh ${CMF} ${OIIOTOOL} ${MAKETX_CLI} ${FIX} ${OUT})
  set_tests_properties(cli.apply.reference-vs-oiiotool-maketx PROPERTIES FIXTURES_REQUIRED cli_fixtures
                       LABELS cli ENVIRONMENT "OCIO=")
else()
  message(STATUS "maketx not found: cli.apply.reference-vs-oiiotool-maketx is not registered")
endif()

# --- the segment pyramid (--method segments, bake-moments --segments) -------------
# Baked for the breakpoints of the table's map (apply-map.exr), applied with
# the ramp (--map ramp.png, other colours): refused unless it fits; applied
# with the map itself it is the reference within float rounding.
set(SP ${OUT}/apply-segments.exr)
cmfilter_apply_case(NAME segments.bake EXIT 0
                    STDOUT "wrote .*apply-segments\\.exr: segment pyramid, 32 x 32, 6 levels.*segments +[0-9]+ breakpoints of [0-9]+ \\(every exact breakpoint\\)"
                    COMMAND bash -c "$0 bake-moments $1 --segments $2 -o $3 | tr '\\n' ' '"
                            ${CMF} ${FIX}/apply-driver.exr ${AT} ${SP})
set_tests_properties(cli.apply.segments.bake PROPERTIES FIXTURES_SETUP apply_segments)
cmfilter_apply_case(NAME segments.equals-reference EXIT 0
                    COMMAND bash -c "set -e\nfor lod in 0 2 3.5\ndo $0 apply --moments $1 --table $2 --lod $lod --method segments -o $4/seg-$lod.exr -q\n$0 apply --moments $3 --table $2 --lod $lod --method reference -o $4/segref-$lod.exr -q\noiiotool --fail 2e-6 --hardfail 2e-6 $4/seg-$lod.exr $4/segref-$lod.exr --diff > /dev/null\ndone"
                            ${CMF} ${SP} ${AT} ${AM} ${OUT})
set_tests_properties(cli.apply.segments.equals-reference PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_segments")
cmfilter_apply_case(NAME segments.info EXIT 0
                    STDOUT "segment pyramid of a driver for the breakpoints.*breakpoints +[-0-9.e ]+"
                    COMMAND bash -c "$0 info $1 | tr '\\n' ' '" ${CMF} ${SP})
set_tests_properties(cli.apply.segments.info PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_segments")
cmfilter_apply_case(NAME bad.segments-other-breakpoints EXIT 3
                    STDERR "segment pyramid '.*apply-segments\\.exr' holds [0-9]+ breakpoints in .*, and the map of table '.*apply-table\\.exr' \\('.*ramp\\.png'\\) does not fit them"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${SP} --table ${AT} --map ${FIX}/ramp.png --lod 1
                                        --method segments -o ${A})
set_tests_properties(cli.apply.bad.segments-other-breakpoints PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs;apply_segments")
cmfilter_apply_case(NAME bad.segments-of-moments EXIT 3
                    STDERR "--method segments reads a segment pyramid, and '.*apply-moments\\.exr' is another pyramid"
                    ABSENT ${A} COMMAND ${CMF} apply --moments ${AM} --table ${AT} --lod 1 --method segments -o ${A})
cmfilter_apply_case(NAME bad.segments-without-tables EXIT 3
                    STDERR "--method segments bakes the breakpoints of colour maps: give their tables with --segments"
                    ABSENT ${OUT}/sp-none.exr
                    COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr --method segments -o ${OUT}/sp-none.exr)
cmfilter_apply_case(NAME bad.segments-max-channels EXIT 3
                    STDERR "the maps need more than 1 channels .* --max-channels allows 1; the closest within 1 channels reaches a mean CIEDE2000 of [0-9.e-]+"
                    ABSENT ${OUT}/sp-none.exr
                    COMMAND ${CMF} bake-moments ${FIX}/apply-driver.exr --segments ${AT} --max-channels 1 -o ${OUT}/sp-none.exr)
# A map recoloured after a tolerance bake that fits the kept breakpoints
# everywhere as well as the baked map (so it is taken) but worse on average
# over the driver (sand-snow with its channels G, R, B): a warning names
# both means and how to re-bake; the baked map itself gets none.
cmfilter_apply_case(NAME segments.recoloured-after-tolerance-warns EXIT 0
                    STDERR "warning: the map of table '.*sand-snow-grb\\.exr' \\('.*sand-snow-grb\\.png'\\) fits the breakpoints of segment pyramid '.*apply-sand-snow-segments\\.exr' worse on average than the maps it was baked for: mean CIEDE2000 [0-9.]+ over the driver's values, against their [0-9.]+ \\(--tolerance 0\\.5 kept their filtered error within [0-9.]+ at LOD 1-8\\). expect more here, or re-bake with bake-moments --segments naming this map's table"
                    COMMAND bash -c "set -e\noiiotool $1 --ch G,R,B --chnames R,G,B -o $3/sand-snow-grb.png\n$0 bake-colormap $1 -o $3/sand-snow.exr -q\n$0 bake-colormap $3/sand-snow-grb.png -o $3/sand-snow-grb.exr -q\n$0 bake-moments $2 --segments $3/sand-snow.exr --tolerance 0.5 -o $3/apply-sand-snow-segments.exr -q\nif $0 apply --moments $3/apply-sand-snow-segments.exr --table $3/sand-snow.exr --lod 1 --method segments -o $3/sand-snow-own.exr 2>&1 | grep warning\nthen exit 1\nfi\n$0 apply --moments $3/apply-sand-snow-segments.exr --table $3/sand-snow-grb.exr --lod 1 --method segments -o $3/sand-snow-grb-out.exr -q"
                            ${CMF} ${LUTS}/sand-snow.png ${FIX}/apply-driver.exr ${OUT})
# A two-colour map: one channel holds its share whatever the colours, so
# --tolerance takes segments (4 bytes a texel, exact) over the colour pyramid
# (12) and the inexact naive (4) and gaussian (8); the file says so.
cmfilter_apply_case(NAME segments.tolerance-two-colours EXIT 0
                    STDOUT "wrote .*apply-step-chosen\\.exr: segment pyramid.*2 breakpoints.*segments +4 B/texel, worst +[0-9.e-]+ \\(LOD [0-9]\\), .*<- chosen.*segment-pyramid.*segments chosen as the cheapest method"
                    COMMAND bash -c "set -e\n$0 bake-colormap $1 -o $3/apply-step-table.exr -q\n$0 bake-moments $2 --tolerance 0.05 --table $3/apply-step-table.exr -o $3/apply-step-chosen.exr | tr '\\n' ' '\n$0 info $3/apply-step-chosen.exr | tr '\\n' ' '"
                            ${CMF} ${LUTS}/step.png ${FIX}/apply-driver.exr ${OUT})
