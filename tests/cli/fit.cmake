# SPDX-License-Identifier: Apache-2.0
# fit: linear relighting models of image stacks, and the stacks' own checks
# (light files and images), each bad input with its exit code and message
# and no output left behind. The stacks come from make_stack_fixtures.sh.
set(STF ${OUT}/stack-fixtures)
add_test(NAME cli.fit.fixtures COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/make_stack_fixtures.sh ${OIIOTOOL} ${STF})
set_tests_properties(cli.fit.fixtures PROPERTIES FIXTURES_SETUP stack_fixtures FIXTURES_REQUIRED cli_dirs
                     LABELS cli)

cmfilter_cli_case(NAME help.fit EXIT 0 STDOUT "STACK" COMMAND ${CMF} fit --help)

# fit_bad(NAME EXIT STDERR LP [ARGS...]): fit LP to an EXR that must not appear.
function(fit_bad name code pattern lp)
  cmfilter_cli_case(NAME bad.fit-${name} EXIT ${code} STDERR "${pattern}" ABSENT ${OUT}/fit-bad-${name}.exr
                    COMMAND ${CMF} fit ${STF}/${lp} -o ${OUT}/fit-bad-${name}.exr ${ARGN})
  set_tests_properties(cli.bad.fit-${name} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures")
endfunction()

fit_bad(count 3 "count\\.lp': line 1 says 9 lights but 8 follow" count.lp)
fit_bad(missing-image 2 "gone\\.png" missing.lp)
fit_bad(size 3 "wide\\.png' is 9x8 but .*img-0\\.png' is 8x8" size.lp)
fit_bad(channels 3 "grey\\.png' has 1 channel but .*img-0\\.png' has 3" channels.lp)
fit_bad(zero-direction 3 "zero\\.lp' line 9: the light direction of 'img-7\\.png' is zero" zero.lp)
fit_bad(infinite-direction 3 "infinite\\.lp' line 9: the light direction of 'img-7\\.png' is not finite" infinite.lp)
fit_bad(below-horizon 3 "below\\.lp' line 9: .*below the horizon" below.lp)
fit_bad(decimal-comma 3 "comma\\.lp' line 9: '0,5' has a decimal comma" comma.lp)
fit_bad(malformed-line 3 "malformed\\.lp' line 5: expected 'image x y z'" malformed.lp)
fit_bad(five-lights 3 "five\\.lp' has 5 lights; a stack needs at least 6" five.lp)
fit_bad(collinear 3 "collinear" collinear.lp)
fit_bad(one-elevation 3 "one elevation, 30(\\.0)? degrees" elevation.lp)
fit_bad(one-elevation-hsh 3 "one elevation" elevation.lp --model hsh3)
fit_bad(model 3 "--model 'ptm' is not a model cmfilter fits" good.lp --model ptm)
fit_bad(missing-lp 2 "no-such\\.lp" no-such.lp)
fit_bad(threshold 3 "--singular-threshold" good.lp --singular-threshold -1)
# A held-out stack that cannot be measured leaves no fit behind either.
fit_bad(held-out-missing 2 "no-such-held\\.lp" good.lp --held-out ${STF}/no-such-held.lp)
fit_bad(held-out-size 3 "is 4x4 with 3; expected the same size and channels" good.lp --held-out ${STF}/small.lp)
cmfilter_cli_case(NAME bad.fit-ptm-hsh EXIT 3 STDERR "hsh2 cannot be written as a \\.ptm" ABSENT ${OUT}/fit-bad.ptm
                  COMMAND ${CMF} fit ${STF}/good.lp --model hsh2 -o ${OUT}/fit-bad.ptm)
cmfilter_cli_case(NAME bad.fit-rti-ptm EXIT 3 STDERR "ptm-rgb cannot be written as a \\.rti" ABSENT ${OUT}/fit-bad.rti
                  COMMAND ${CMF} fit ${STF}/good.lp --model ptm-rgb -o ${OUT}/fit-bad.rti)
cmfilter_cli_case(NAME bad.fit-ptm-linear EXIT 3 STDERR "--encoding linear cannot be written" ABSENT ${OUT}/fit-bad.ptm
                  COMMAND ${CMF} fit ${STF}/good.lp --encoding linear -o ${OUT}/fit-bad.ptm)
cmfilter_cli_case(NAME bad.fit-extension EXIT 3 STDERR "expected a \\.exr, \\.ptm or \\.rti" ABSENT ${OUT}/fit-bad.png
                  COMMAND ${CMF} fit ${STF}/good.lp -o ${OUT}/fit-bad.png)
foreach(t IN ITEMS ptm-hsh rti-ptm ptm-linear extension)
  set_tests_properties(cli.bad.fit-${t} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures")
endforeach()

# A good stack fits with every model, to every format.
foreach(m IN ITEMS ptm-rgb ptm-lrgb hsh2 hsh3)
  cmfilter_cli_case(NAME fit.good-${m} EXIT 0 STDOUT "${m} fit, 8 x 8, 3 channels"
                    COMMAND ${CMF} fit ${STF}/good.lp --model ${m} -o ${OUT}/fit-good-${m}.exr)
  set_tests_properties(cli.fit.good-${m} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures"
                       FIXTURES_SETUP fit_good_${m})
endforeach()
cmfilter_cli_case(NAME fit.good-ptm EXIT 0 STDOUT "quantisation" COMMAND ${CMF} fit ${STF}/good.lp -o ${OUT}/fit-good.ptm)
cmfilter_cli_case(NAME fit.good-rti EXIT 0 STDOUT "quantisation"
                  COMMAND ${CMF} fit ${STF}/good.lp --model hsh3 -o ${OUT}/fit-good.rti)
set_tests_properties(cli.fit.good-ptm PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures" FIXTURES_SETUP fit_good_ptm)
set_tests_properties(cli.fit.good-rti PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures" FIXTURES_SETUP fit_good_rti)
# Constant images under every light: every model reproduces them (to 8-bit
# quantisation in the .ptm and .rti).
add_test(NAME cli.fit.constant-stack-exact
         COMMAND bash -c "$0 fit $1/good.lp --json -o $2/fit-json.exr | python3 -c 'import json,sys; j=json.load(sys.stdin); e=j[\"training_error\"]; assert e[\"rmse\"] < 1e-5 and e[\"delta_e_max\"] < 1e-3, e'"
                 ${CMF} ${STF} ${OUT})
set_tests_properties(cli.fit.constant-stack-exact PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures" LABELS cli)

# info on a stack, a BTF manifest-less stack's conditioning, and on fits.
cmfilter_cli_case(NAME info.stack EXIT 0 STDOUT "image-stack" COMMAND ${CMF} info ${STF}/good.lp)
cmfilter_cli_case(NAME info.stack-degenerate EXIT 0 STDOUT "condition_number_ptm-rgb +unusable: .*one elevation"
                  COMMAND ${CMF} info ${STF}/elevation.lp)
cmfilter_cli_case(NAME info.fit EXIT 0 STDOUT "linear-fit" COMMAND ${CMF} info ${OUT}/fit-good-ptm-rgb.exr)
cmfilter_cli_case(NAME info.ptm EXIT 0 STDOUT "display-encoded" COMMAND ${CMF} info ${OUT}/fit-good.ptm)
cmfilter_cli_case(NAME info.rti EXIT 0 STDOUT "hsh3" COMMAND ${CMF} info ${OUT}/fit-good.rti)
set_tests_properties(cli.info.stack cli.info.stack-degenerate PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures")
set_tests_properties(cli.info.fit PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm-rgb")
set_tests_properties(cli.info.ptm PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm")
set_tests_properties(cli.info.rti PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_rti")

# The bundled stacks (examples/make_stacks.sh, seconds), fitted and measured
# against make-stack's exact ground truth: on the near-diffuse surface a
# linear model follows the light (HSH 3 within a mean CIEDE2000 of 0.5 at
# held-out lights it was not fitted to; docs/stacks.md measures 0.15), and
# the brightest direction of a diffuse surface is its normal (HSH 3 within
# 2.5 degrees on average of the true mean normals; measured 1.2).
set(BUNDLED ${OUT}/bundled-stacks)
add_test(NAME cli.stacks.bundled
         COMMAND bash -c "set -e; bash $0/examples/make_stacks.sh $1 $2 > /dev/null; mkdir -p $2/near-diffuse-held
$1 make-stack --from $2/near-diffuse/stack.json --dome regular:16 --min-elevation 20 -o $2/near-diffuse-held/stack.lp -q"
                 ${PROJECT_SOURCE_DIR} ${CMF} ${BUNDLED})
set_tests_properties(cli.stacks.bundled PROPERTIES FIXTURES_SETUP bundled_stacks FIXTURES_REQUIRED cli_dirs
                     LABELS cli ENVIRONMENT "OCIO=")
add_test(NAME cli.stacks.near-diffuse-held-out
         COMMAND bash -c "$0 fit $1/near-diffuse/stack.lp --model hsh3 -o $1/nd-hsh3.exr --held-out $1/near-diffuse-held/stack.lp --json | python3 -c 'import json,sys; e=json.load(sys.stdin)[\"held_out_error\"]; print(e); assert e[\"lights\"] == 16 and e[\"delta_e_mean\"] < 0.5, e'"
                 ${CMF} ${BUNDLED})
add_test(NAME cli.stacks.near-diffuse-normals
         COMMAND bash -c "$0 normals $1/nd-hsh3.exr --reference $1/near-diffuse/stack.normals.exr --json | python3 -c 'import json,sys; a=json.load(sys.stdin)[\"angle_degrees\"]; print(a); assert a[\"count\"] == 4096 and a[\"mean\"] < 2.5, a'"
                 ${CMF} ${BUNDLED})
set_tests_properties(cli.stacks.near-diffuse-held-out PROPERTIES FIXTURES_REQUIRED bundled_stacks
                     FIXTURES_SETUP bundled_fit LABELS cli ENVIRONMENT "OCIO=")
set_tests_properties(cli.stacks.near-diffuse-normals PROPERTIES FIXTURES_REQUIRED "bundled_stacks;bundled_fit"
                     LABELS cli ENVIRONMENT "OCIO=")
# info on the bundled BTF manifest.
cmfilter_cli_case(NAME info.btf EXIT 0 STDOUT "btf-manifest" COMMAND ${CMF} info ${BUNDLED}/multiview/btf.json)
set_tests_properties(cli.info.btf PROPERTIES FIXTURES_REQUIRED "cli_dirs;bundled_stacks")
