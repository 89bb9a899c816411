# SPDX-License-Identifier: Apache-2.0
# fit --model lafortune / lafortune-rgb, and relight, info and normals on
# Lafortune fits: good fits of the stack fixtures (12 lights) and of the
# bundled stacks, and every bad input with its exit code, message and no
# output left behind.

# Good fits of the 8 x 8, 12-light fixture: luminance 1 and 2 lobes, auto
# (at most (12 - 1) / 4 = 2 lobes), rgb.
foreach(c IN ITEMS "1;lafortune;1;1 lobe \\(luminance" "2;lafortune;2;2 lobes \\(luminance"
               "auto;lafortune;auto;auto lobes, at most 2 lobes" "rgb;lafortune-rgb;2;2 lobes per channel")
  list(GET c 0 n)
  list(GET c 1 m)
  list(GET c 2 l)
  list(GET c 3 lobes_line)
  cmfilter_cli_case(NAME lafortune.fit-${n} EXIT 0 STDOUT "${lobes_line}"
                    COMMAND ${CMF} fit ${STF}/good.lp --model ${m} --lobes ${l} -o ${OUT}/laf-good-${n}.exr)
  set_tests_properties(cli.lafortune.fit-${n} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures"
                       FIXTURES_SETUP laf_good_${n})
endforeach()
# --json: the linear fits' keys and the lobes; the histogram counts every
# texel once (64), or every texel channel (192) for rgb. The training stack
# as held-out stack: the streamed error (held out) is the in-memory one
# (training), the mean to rounding.
foreach(c IN ITEMS "lafortune;auto;64" "lafortune-rgb;2;192")
  list(GET c 0 m)
  list(GET c 1 l)
  list(GET c 2 total)
  add_test(NAME cli.lafortune.json-${m}
           COMMAND bash -c "$0 fit $1/good.lp --model $3 --lobes $4 --held-out $1/good.lp --json -o $2/laf-json-$3.exr | python3 -c 'import json,sys; j=json.load(sys.stdin); print(j); h=j[\"lobe_histogram\"]; assert sum(h) == int(sys.argv[1]) and len(h) == j[\"lobes\"] + 1, h; assert j[\"size\"] == [8, 8] and j[\"lights\"] == 12 and j[\"bytes\"] > 0 and j[\"fallbacks\"] >= 0 and j[\"view\"] == [0, 0, 1], j; t=j[\"training_error\"]; e=j[\"held_out_error\"]; assert t[\"lights\"] == 12 and all(e[k] == t[k] for k in (\"lights\", \"rmse\", \"delta_e_p95\", \"delta_e_max\")) and abs(e[\"delta_e_mean\"] - t[\"delta_e_mean\"]) <= 1e-12 * t[\"delta_e_mean\"], (t, e); assert all(k in j[\"seconds\"] for k in (\"read\", \"fit\", \"total\"))' $5"
                   ${CMF} ${STF} ${OUT} ${m} ${l} ${total})
  set_tests_properties(cli.lafortune.json-${m} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures" LABELS cli
                       ENVIRONMENT "OCIO=")
endforeach()

# Relit from the fits: PNG and EXR (finite, the fixture's size), at the
# fitted view and another; measured against the stack.
foreach(n IN ITEMS 1 2 auto rgb)
  cmfilter_cli_case(NAME lafortune.relight-png-${n} EXIT 0 STDOUT "relit at \\(0\\.3.* seen from \\(0, 0, 1\\)"
                    COMMAND ${CMF} relight ${OUT}/laf-good-${n}.exr --light 0.3,0.2,0.9 -o ${OUT}/laf-relit-${n}.png)
  cmfilter_cli_case(NAME lafortune.relight-reference-${n} EXIT 0 STDOUT "CIEDE2000 mean"
                    COMMAND ${CMF} relight ${OUT}/laf-good-${n}.exr --reference ${STF}/good.lp)
  set_tests_properties(cli.lafortune.relight-png-${n} cli.lafortune.relight-reference-${n}
                       PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;laf_good_${n}")
endforeach()
add_test(NAME cli.lafortune.relight-exr-view
         COMMAND bash -c "set -e; $0 relight $1/laf-good-2.exr --light -0.4,0.5,0.77 --view 0.6,0,0.8 -o $1/laf-relit-view.exr | grep -E 'seen from \\(0\\.6, 0, 0\\.8\\)'; bash $2 $3 $1/laf-relit-view.exr 8 8 --nonnegative"
                 ${CMF} ${OUT} ${CHECK_FINITE} ${OIIOTOOL})
set_tests_properties(cli.lafortune.relight-exr-view PROPERTIES FIXTURES_REQUIRED "cli_dirs;laf_good_2" LABELS cli
                     ENVIRONMENT "OCIO=")

# info: the kind, the model, variant, lobes and view, and the parameters.
cmfilter_cli_case(NAME lafortune.info EXIT 0
                  STDOUT "variant luminance, a diffuse term and 2 lobes times a base colour, fitted at the view \\(0, 0, 1\\)"
                  COMMAND ${CMF} info ${OUT}/laf-good-2.exr)
cmfilter_cli_case(NAME lafortune.info-auto EXIT 0 STDOUT "at most 2 lobes chosen per texel"
                  COMMAND ${CMF} info ${OUT}/laf-good-auto.exr)
cmfilter_cli_case(NAME lafortune.info-rgb EXIT 0 STDOUT "lobe_histogram +[0-9]+,[0-9]+,[0-9]+"
                  COMMAND ${CMF} info ${OUT}/laf-good-rgb.exr)
set_tests_properties(cli.lafortune.info PROPERTIES FIXTURES_REQUIRED "cli_dirs;laf_good_2")
set_tests_properties(cli.lafortune.info-auto PROPERTIES FIXTURES_REQUIRED "cli_dirs;laf_good_auto")
set_tests_properties(cli.lafortune.info-rgb PROPERTIES FIXTURES_REQUIRED "cli_dirs;laf_good_rgb")

# fit_lafortune_bad(NAME EXIT STDERR LP [ARGS...]): a Lafortune fit of LP to
# an EXR that must not appear.
function(fit_lafortune_bad name code pattern lp)
  cmfilter_cli_case(NAME bad.lafortune-${name} EXIT ${code} STDERR "${pattern}" ABSENT ${OUT}/laf-bad-${name}.exr
                    COMMAND ${CMF} fit ${lp} -o ${OUT}/laf-bad-${name}.exr ${ARGN})
  set_tests_properties(cli.bad.lafortune-${name} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;bundled_stacks")
endfunction()
set(GOOD ${STF}/good.lp)
set(BTF ${BUNDLED}/multiview/btf.json)
fit_lafortune_bad(lobes-8 3 "--lobes 8 is invalid: a luminance fit takes 1 to 7 lobes" ${GOOD} --model lafortune --lobes 8)
fit_lafortune_bad(lobes-0 3 "--lobes 0 is invalid" ${GOOD} --model lafortune --lobes 0)
fit_lafortune_bad(lobes-rgb-3 3 "--lobes 3 is invalid: a rgb fit takes 1 to 2 lobes" ${GOOD} --model lafortune-rgb --lobes 3)
fit_lafortune_bad(lobes-word 3 "--lobes 'many' is invalid \\(expected a lobe count or auto\\)" ${GOOD} --model lafortune --lobes many)
fit_lafortune_bad(tolerance-0 3 "--tolerance 0 is invalid: the auto lobe count needs an RMS tolerance above 0" ${GOOD}
                  --model lafortune --lobes auto --tolerance 0)
fit_lafortune_bad(tolerance-negative 3 "--tolerance -1 is invalid" ${GOOD} --model lafortune --lobes auto --tolerance -1)
fit_lafortune_bad(tolerance-fixed 3 "--tolerance chooses the lobe count per texel: it needs --lobes auto" ${GOOD}
                  --model lafortune --lobes 2 --tolerance 0.01)
fit_lafortune_bad(min-gain 3 "--min-gain 1 is invalid: expected a fraction in .0, 1\\)" ${GOOD}
                  --model lafortune --lobes auto --min-gain 1)
fit_lafortune_bad(max-lobes 3 "--max-lobes 3 needs at least 13 lights, but .*good\\.lp' has 12" ${GOOD}
                  --model lafortune --lobes auto --max-lobes 3)
fit_lafortune_bad(view-below 3 "--view '0,0.5,-1' is below the horizon" ${GOOD} --model lafortune --view 0,0.5,-1)
fit_lafortune_bad(view-horizon 3 "--view \\(1, 0, 0\\) is invalid: expected a direction above the horizon" ${GOOD}
                  --model lafortune --view 1,0,0)
fit_lafortune_bad(too-few-lights 3 "--lobes 3 needs at least 13 lights \\(rho_d and 4 parameters per lobe\\), but the stack .*good\\.lp' has 12"
                  ${GOOD} --model lafortune --lobes 3)
fit_lafortune_bad(iterations 3 "--max-iterations 0 is invalid" ${GOOD} --model lafortune --max-iterations 0)
fit_lafortune_bad(function-tolerance 3 "--function-tolerance 1 is invalid" ${GOOD} --model lafortune --function-tolerance 1)
fit_lafortune_bad(linear-flag 3 "--singular-threshold is an option of the linear models, not of lafortune" ${GOOD}
                  --model lafortune --singular-threshold 1e-3)
fit_lafortune_bad(lobes-linear 3 "--lobes is an option of the Lafortune models" ${GOOD} --model hsh3 --lobes 2)
fit_lafortune_bad(slot-range 3 "--slot 7 is out of range: .*btf\\.json' has 7 view slots \\(expected 0 to 6\\)" ${BTF}
                  --model lafortune --slot 7)
fit_lafortune_bad(slot-lp 3 "--slot 1 picks a view slot of a BTF manifest, but .*good\\.lp' is a light file" ${GOOD}
                  --model lafortune --slot 1)
fit_lafortune_bad(view-manifest 3 "--view cannot be given with the BTF manifest .*btf\\.json'" ${BTF}
                  --model lafortune --slot 1 --view 0,0,1)
fit_lafortune_bad(held-out-size 3 "is 4x4 with 3; expected the same size and channels" ${GOOD} --model lafortune
                  --lobes 1 --held-out ${STF}/small.lp)
foreach(ext IN ITEMS ptm rti)
  cmfilter_cli_case(NAME bad.lafortune-${ext} EXIT 3
                    STDERR "--model lafortune cannot be written as a \\.${ext}: Lafortune lobes go to an \\.exr"
                    ABSENT ${OUT}/laf-bad.${ext} COMMAND ${CMF} fit ${GOOD} --model lafortune -o ${OUT}/laf-bad.${ext})
  set_tests_properties(cli.bad.lafortune-${ext} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures")
endforeach()

# relight, normals: a view a PTM cannot render, Lafortune normals, a bad slot.
cmfilter_cli_case(NAME bad.relight-linear-view EXIT 3 STDERR "a PTM/HSH holds one view" ABSENT ${OUT}/relit-bad-view.png
                  COMMAND ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr --light 0,0,1 --view 0.5,0,0.866
                  -o ${OUT}/relit-bad-view.png)
set_tests_properties(cli.bad.relight-linear-view PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm-rgb")
cmfilter_cli_case(NAME bad.relight-lafortune-view-below EXIT 3 STDERR "--view '0,0,-1' is below the horizon"
                  ABSENT ${OUT}/laf-relit-bad.png
                  COMMAND ${CMF} relight ${OUT}/laf-good-2.exr --light 0,0,1 --view 0,0,-1 -o ${OUT}/laf-relit-bad.png)
cmfilter_cli_case(NAME bad.normals-lafortune EXIT 3 STDERR "is a lafortune fit: normals takes a linear fit"
                  ABSENT ${OUT}/laf-normals-bad.exr
                  COMMAND ${CMF} normals ${OUT}/laf-good-2.exr -o ${OUT}/laf-normals-bad.exr)
set_tests_properties(cli.bad.relight-lafortune-view-below cli.bad.normals-lafortune
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;laf_good_2")
cmfilter_cli_case(NAME bad.relight-slot-range EXIT 3 STDERR "--slot 9 is out of range"
                  COMMAND ${CMF} relight ${OUT}/laf-good-2.exr --reference ${BTF} --slot 9)
set_tests_properties(cli.bad.relight-slot-range PROPERTIES FIXTURES_REQUIRED "cli_dirs;laf_good_2;bundled_stacks")

# The bundled stacks. Near-diffuse (64 x 64, 64 lights): the error fit
# reports at the training lights (the stack held) is relight --reference's
# (streamed from the files): the same sums in the same order; at the 16
# held-out lights two lobes are within a mean CIEDE2000 of 2.5 (measured
# 1.86).
add_test(NAME cli.lafortune.near-diffuse
         COMMAND bash -c "set -e; $0 fit $1/near-diffuse/stack.lp --model lafortune --lobes 2 -o $1/nd-laf2.exr --held-out $1/near-diffuse-held/stack.lp --json > $1/nd-laf2.json
$0 relight $1/nd-laf2.exr --reference $1/near-diffuse/stack.lp --json > $1/nd-laf2-reference.json
python3 -c 'import json,sys; f=json.load(open(sys.argv[1])); r=json.load(open(sys.argv[2])); t=f[\"training_error\"]; h=f[\"held_out_error\"]; print(t, h, r[\"rmse\"]); assert r[\"lights\"] == 64 and abs(r[\"rmse\"] - t[\"rmse\"]) <= 1e-12 * t[\"rmse\"] and abs(r[\"delta_e\"][\"max\"] - t[\"delta_e_max\"]) <= 1e-9, (r, t); assert h[\"lights\"] == 16 and h[\"delta_e_mean\"] < 2.5, h; assert sum(f[\"lobe_histogram\"]) == 4096' $1/nd-laf2.json $1/nd-laf2-reference.json"
                 ${CMF} ${BUNDLED})
set_tests_properties(cli.lafortune.near-diffuse PROPERTIES FIXTURES_REQUIRED bundled_stacks LABELS cli
                     ENVIRONMENT "OCIO=")
# A BTF view slot (the multiview manifest's slot 1, at 60 degrees): the
# slot's view is the fit's, relight --reference with the same slot renders
# it there and matches the fit's own training error; rendered from the
# zenith instead, it is compared at a view its images were not taken from.
add_test(NAME cli.lafortune.btf-slot
         COMMAND bash -c "set -e; $0 fit $1/multiview/btf.json --slot 1 --model lafortune --lobes auto -o $1/mv-laf.exr --json > $1/mv-laf.json
$0 relight $1/mv-laf.exr --reference $1/multiview/btf.json --slot 1 --json > $1/mv-laf-slot.json
$0 relight $1/mv-laf.exr --reference $1/multiview/view-01/stack.lp --view 0,0,1 --json > $1/mv-laf-zenith.json
python3 -c 'import json,sys; f, s, z = (json.load(open(p)) for p in sys.argv[1:4]); v=f[\"view\"]; print(v, f[\"training_error\"], s[\"rmse\"], z[\"rmse\"]); assert f[\"slot\"] == 1 and abs(v[0] - 0.5) < 1e-3 and abs(v[1]) < 1e-9 and abs(v[2] - 0.866) < 1e-3, v; assert s[\"slot\"] == 1 and max(abs(a - b) for a, b in zip(s[\"view\"], v)) < 1e-12 and abs(s[\"rmse\"] - f[\"training_error\"][\"rmse\"]) <= 1e-12 * s[\"rmse\"], s; assert z[\"view\"] == [0, 0, 1] and z[\"rmse\"] != s[\"rmse\"], z' $1/mv-laf.json $1/mv-laf-slot.json $1/mv-laf-zenith.json"
                 ${CMF} ${BUNDLED})
set_tests_properties(cli.lafortune.btf-slot PROPERTIES FIXTURES_REQUIRED bundled_stacks LABELS cli ENVIRONMENT "OCIO=")
