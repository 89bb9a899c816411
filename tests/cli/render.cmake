# SPDX-License-Identifier: Apache-2.0
# render: a scene file rendered per pixel.
cmfilter_cli_case(NAME help.render EXIT 0 STDOUT "--footprint" COMMAND ${CMF} render --help)

set(RO ${OUT}/render-bad.png)
cmfilter_cli_case(NAME render.gaussian EXIT 0 STDOUT "32 x 18, gaussian, 1 ray\\(s\\) per pixel"
                  COMMAND ${CMF} render ${SC}/good.json --method gaussian -o ${OUT}/render-gaussian.png)
cmfilter_cli_case(NAME render.supersample-json EXIT 0 STDOUT "\"samples\": 4"
                  COMMAND ${CMF} render ${SC}/good.json --method supersample --spp 4 --json
                          -o ${OUT}/render-ss.exr --aov ${OUT}/render-ss)
cmfilter_cli_case(NAME render.edge-coverage-json EXIT 0 STDOUT "\"edge_coverage\": true"
                  COMMAND ${CMF} render ${SC}/good.json --method naive --json -o ${OUT}/render-edges.exr)
cmfilter_cli_case(NAME render.no-edge-coverage-json EXIT 0 STDOUT "\"edge_coverage\": false"
                  COMMAND ${CMF} render ${SC}/good.json --method gaussian --no-edge-coverage --json
                          -o ${OUT}/render-no-edges.exr)
# --size replaces the scene's 32 x 18 for a preview: the file OpenImageIO
# reads back is 40 x 10; past a scene's limits it is refused, naming --size.
cmfilter_cli_case(NAME render.size EXIT 0 STDOUT "40 x 10, gaussian"
                  COMMAND ${CMF} render ${SC}/good.json --size 40x10 -o ${OUT}/render-size.exr)
set_tests_properties(cli.render.size PROPERTIES FIXTURES_SETUP render_size)
add_test(NAME cli.render.size-info COMMAND ${OIIOTOOL} --info ${OUT}/render-size.exr)
set_tests_properties(cli.render.size-info PROPERTIES FIXTURES_REQUIRED render_size LABELS cli
    PASS_REGULAR_EXPRESSION "40 x +10, 3 channel, float openexr")
cmfilter_cli_case(NAME render.bad.probes EXIT 3 STDERR "error: --probes 0 is out of range \\(expected 1 to 64\\)"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --probes 0 -o ${RO})
cmfilter_cli_case(NAME render.bad.size-side EXIT 3 STDERR "--size '20000x10' has a side above 16384"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --size 20000x10 -o ${RO})
cmfilter_cli_case(NAME render.bad.size-pixels EXIT 3 STDERR "--size '16384x16384' is 268435456 pixels, above"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --size 16384x16384 -o ${RO})
cmfilter_cli_case(NAME render.bad.size-malformed EXIT 3 STDERR "--size '40' is not a size"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --size 40 -o ${RO})
cmfilter_cli_case(NAME render.bad.malformed-json EXIT 3 STDERR "malformed.json: malformed JSON at line [0-9]+, column"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/malformed.json -o ${RO})
cmfilter_cli_case(NAME render.bad.unknown-key EXIT 3 STDERR "/camera/fovv: unknown key"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/unknown-key.json -o ${RO})
cmfilter_cli_case(NAME render.bad.missing-file EXIT 3 STDERR "/surfaces/0/material/driver/sigma_table: .*no-such-table\\.exr"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/missing-file.json -o ${RO})
cmfilter_cli_case(NAME render.bad.scene-missing EXIT 2 STDERR "no-such-scene\\.json"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/no-such-scene.json -o ${RO})
cmfilter_cli_case(NAME render.bad.camera-nowhere EXIT 3 STDERR "camera-nowhere.json: /camera"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/camera-nowhere.json -o ${RO})
cmfilter_cli_case(NAME render.bad.resolution-zero EXIT 3 STDERR "/camera/resolution"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/resolution-zero.json -o ${RO})
cmfilter_cli_case(NAME render.bad.resolution-absurd EXIT 3 STDERR "/camera/resolution.*16384"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/resolution-absurd.json -o ${RO})
cmfilter_cli_case(NAME render.bad.spp-zero EXIT 3 STDERR "--spp 0 is out of range"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --method supersample --spp 0 -o ${RO})
cmfilter_cli_case(NAME render.bad.method EXIT 3 STDERR "method 'exact-ish' is unknown"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --method exact-ish -o ${RO})
cmfilter_cli_case(NAME render.bad.footprint EXIT 3 STDERR "footprint width 'wide' is unknown"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --footprint wide -o ${RO})
cmfilter_cli_case(NAME render.bad.table-range EXIT 3 STDERR "domain \\[5, 6\\] does not meet the driver's values"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/domain-off-driver.json -o ${RO})
cmfilter_cli_case(NAME render.bad.sigma-table-other-noise EXIT 3 STDERR "was baked for the noise 'fbm:base=gradient"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/sigma-table-other-noise.json -o ${RO})
# Texture drivers: a driver image (its moments baked in process) and moment
# pyramids from the apply inputs, in scenes written here with their paths.
cmfilter_cli_case(NAME render.texture-image-gaussian EXIT 0 STDOUT "32 x 18, gaussian, 1 ray\\(s\\) per pixel, [0-9]+ pixels"
                  COMMAND ${CMF} render ${SC}/texture-driver.json --method gaussian -o ${OUT}/render-texture-gaussian.png
                          --aov ${OUT}/render-texture-gaussian)
cmfilter_cli_case(NAME render.texture-image-reference EXIT 0 STDOUT "\"samples\": 1024"
                  COMMAND ${CMF} render ${SC}/texture-driver.json --method reference --json
                          -o ${OUT}/render-texture-reference.exr)
cmfilter_cli_case(NAME render.moments-gaussian EXIT 0 STDOUT "32 x 18, gaussian"
                  COMMAND ${CMF} render ${SCB}/moments.json --method gaussian -o ${OUT}/render-moments-gaussian.png)
cmfilter_cli_case(NAME render.moments-supersample EXIT 0 STDOUT "32 x 18, supersample, 4 ray"
                  COMMAND ${CMF} render ${SCB}/moments.json --method supersample --spp 4
                          -o ${OUT}/render-moments-supersample.png)
# With the recorded driver gone, naive and gaussian need only the moments;
# supersample, reference and exact name the missing file.
cmfilter_cli_case(NAME render.moments-source-gone-naive EXIT 0 STDOUT "32 x 18, naive"
                  COMMAND ${CMF} render ${SCB}/moments-source-gone.json --method naive
                          -o ${OUT}/render-moments-gone-naive.png)
cmfilter_cli_case(NAME render.moments-source-gone-gaussian EXIT 0 STDOUT "32 x 18, gaussian"
                  COMMAND ${CMF} render ${SCB}/moments-source-gone.json --method gaussian
                          -o ${OUT}/render-moments-gone-gaussian.exr)
cmfilter_cli_case(NAME render.bad.moments-source-gone EXIT 2
                  STDERR "moments-source-gone\\.json: /surfaces/0/material/driver/moments: cannot read driver '[^']*apply-gone-driver\\.exr' recorded in '.*apply-gone-moments\\.exr' \\(cmfilter:source\\): no such file; supersample reads the driver's texels"
                  ABSENT ${RO} COMMAND ${CMF} render ${SCB}/moments-source-gone.json --method supersample -o ${RO})
cmfilter_cli_case(NAME render.bad.moments-source-gone-reference EXIT 2
                  STDERR "moments-source-gone\\.json: /surfaces/0/material/driver/moments: cannot read driver '[^']*apply-gone-driver\\.exr' recorded in '.*apply-gone-moments\\.exr' \\(cmfilter:source\\): no such file; reference reads the driver's texels"
                  ABSENT ${RO} COMMAND ${CMF} render ${SCB}/moments-source-gone.json --method reference -o ${RO})
cmfilter_cli_case(NAME render.bad.moments-source-gone-exact EXIT 2
                  STDERR "moments-source-gone\\.json: /surfaces/0/material/driver/moments: cannot read driver '[^']*apply-gone-driver\\.exr' recorded in '.*apply-gone-moments\\.exr' \\(cmfilter:source\\): no such file; exact bakes its histograms from the driver's texels"
                  ABSENT ${RO} COMMAND ${CMF} render ${SCB}/moments-source-gone.json --method exact -o ${RO})
set_tests_properties(cli.render.moments-gaussian cli.render.moments-supersample cli.render.moments-source-gone-naive
                     cli.render.moments-source-gone-gaussian cli.render.bad.moments-source-gone
                     cli.render.bad.moments-source-gone-reference cli.render.bad.moments-source-gone-exact
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs")
# --method auto: each texture's cheapest method for --tolerance, measured
# (a tolerance everything meets takes naive), recorded in the image; it needs
# a tolerance.
cmfilter_cli_case(NAME render.auto-records-choice EXIT 0
                  STDOUT "cmfilter:method: \"auto\".*cmfilter:method_tolerance: 100.*cmfilter:texture_methods: \"0: naive\""
                  COMMAND bash -c "set -o pipefail && ($0 render $1 --method auto --tolerance 100 --measure-lods 1 -o $2 -q && oiiotool --info -v $2) | tr '\\n' ' '"
                          ${CMF} ${SCB}/texture-auto.json ${OUT}/render-auto.exr)
cmfilter_cli_case(NAME render.bad.auto-without-tolerance EXIT 3
                  STDERR "--method auto chooses each texture's and microsurface's method and each noise's sub-footprints for a tolerance: it needs --tolerance DE"
                  ABSENT ${RO} COMMAND ${CMF} render ${SCB}/texture-auto.json --method auto -o ${RO})
# The exact method: a driver image with four values (its histograms baked in
# process); a noise driver and a driver with 1024 values are refused.
cmfilter_cli_case(NAME render.texture-image-exact EXIT 0 STDOUT "32 x 18, exact, 1 ray\\(s\\) per pixel, [0-9]+ pixels"
                  COMMAND ${CMF} render ${SCB}/texture-quantised.json --method exact -o ${OUT}/render-texture-exact.png)
cmfilter_cli_case(NAME render.bad.exact-noise EXIT 3
                  STDERR "good\\.json: /surfaces/0/material/driver: exact needs a texture driver with at most 256 distinct values; noise drivers have no exact filtering distribution"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --method exact -o ${RO})
cmfilter_cli_case(NAME render.bad.exact-too-many-values EXIT 3
                  STDERR "moments\\.json: /surfaces/0/material/driver/moments: driver '.*apply-driver\\.exr' has 1024 distinct values"
                  ABSENT ${RO} COMMAND ${CMF} render ${SCB}/moments.json --method exact -o ${RO})
set_tests_properties(cli.render.bad.exact-too-many-values PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;apply_inputs")
# color-pyramid: the box means of C0(f) baked in process from the driver's
# level 0; on the four-valued driver the histograms' exact colours, a second
# computation of the same box means (float rounding apart). A noise is refused.
cmfilter_cli_case(NAME render.texture-color-pyramid-equals-exact EXIT 0
                  COMMAND bash -c "set -e\n$0 render $1 --method color-pyramid -o $2/render-cp.exr -q\n$0 render $1 --method exact -o $2/render-cp-exact.exr -q\noiiotool --fail 1e-4 --hardfail 1e-4 $2/render-cp.exr $2/render-cp-exact.exr --diff > /dev/null"
                          ${CMF} ${SCB}/texture-quantised.json ${OUT})
cmfilter_cli_case(NAME render.bad.color-pyramid-noise EXIT 3
                  STDERR "surface 0: color-pyramid needs a texture driver"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --method color-pyramid -o ${RO})
# --method auto at a tolerance no moments method meets on a driver of many
# values through the hard-edged map: the colour pyramid (12 bytes a texel).
cmfilter_cli_case(NAME render.auto-color-pyramid EXIT 0
                  STDOUT "cmfilter:texture_methods: \"0: color-pyramid\""
                  COMMAND bash -c "set -o pipefail && ($0 render $1 --method auto --tolerance 0.05 --measure-lods 1,2 -o $2 -q && oiiotool --info -v $2) | tr '\\n' ' '"
                          ${CMF} ${SC}/texture-driver.json ${OUT}/render-auto-cp.exr)
# segments: the ramp means between the map's breakpoints, baked in process
# for every breakpoint of the map: on the four-valued driver the same box
# means as color-pyramid (float rounding apart). A noise is refused. A pyramid
# baked once and named by driver/segments recolours a map on its breakpoints
# and refuses a map of others (check_render_segments.sh).
cmfilter_cli_case(NAME render.texture-segments-equals-color-pyramid EXIT 0
                  COMMAND bash -c "set -e\n$0 render $1 --method segments -o $2/render-seg.exr -q\n$0 render $1 --method color-pyramid -o $2/render-seg-cp.exr -q\noiiotool --fail 1e-4 --hardfail 1e-4 $2/render-seg.exr $2/render-seg-cp.exr --diff > /dev/null"
                          ${CMF} ${SCB}/texture-quantised.json ${OUT})
cmfilter_cli_case(NAME render.segments-reports-its-pyramid EXIT 0
                  STDOUT "surface 0: segment pyramid baked for this render, 2 breakpoints, 1 channel \\(4 bytes a texel\\), the map's colours at them, read into memory"
                  COMMAND ${CMF} render ${SC}/texture-step.json --method segments -o ${OUT}/render-seg-report.exr)
cmfilter_cli_case(NAME render.bad.segments-noise EXIT 3
                  STDERR "surface 0: segments needs a texture driver"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --method segments -o ${RO})
add_test(NAME cli.render.segments-baked-once
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_render_segments.sh ${CMF} ${OIIOTOOL} ${PROJECT_SOURCE_DIR} ${OUT})
set_tests_properties(cli.render.segments-baked-once PROPERTIES LABELS cli FIXTURES_REQUIRED cli_dirs ENVIRONMENT "OCIO=")
# --method auto through a two-colour map at a tolerance no moments method
# meets: segments, one channel (4 bytes a texel, exact), before the colour
# pyramid's 12.
cmfilter_cli_case(NAME render.auto-segments EXIT 0
                  STDOUT "cmfilter:texture_methods: \"0: segments\""
                  COMMAND bash -c "set -o pipefail && ($0 render $1 --method auto --tolerance 0.05 --measure-lods 1,2 -o $2 -q && oiiotool --info -v $2) | tr '\\n' ' '"
                          ${CMF} ${SC}/texture-step.json ${OUT}/render-auto-seg.exr)
cmfilter_cli_case(NAME render.bad.output-extension EXIT 3 STDERR "wrong extension"
                  ABSENT ${OUT}/render-bad.tif COMMAND ${CMF} render ${SC}/good.json -o ${OUT}/render-bad.tif)
# Tables fitted to a tolerance over the surface's sigma range, and the small-sigma shortcut.
cmfilter_cli_case(NAME render.tolerance EXIT 0
                  STDOUT "surface 0: 128 x 8 sqrt table, 12288 bytes \\(1\\.56% of 256 x 256\\), lookup CIEDE2000 p99\\.9 [0-9.]+ <= 1 over sigma \\[0, 0\\.245\\]; C0\\(mean\\) directly below sigma"
                  COMMAND ${CMF} render ${SC}/good.json --tolerance 1 -o ${OUT}/render-tolerance.png)
cmfilter_cli_case(NAME render.tolerance-json EXIT 0 STDOUT "\"plain\": [0-9]+"
                  COMMAND ${CMF} render ${SC}/good.json --tolerance 1 --shortcut 0.2 --json -o ${OUT}/render-tolerance.exr)
cmfilter_cli_case(NAME render.bad.tolerance-zero EXIT 3 STDERR "--tolerance 0 is invalid \\(expected a CIEDE2000 difference > 0\\)"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --tolerance 0 -o ${RO})
cmfilter_cli_case(NAME render.bad.shortcut-negative EXIT 3 STDERR "--shortcut -1 is invalid"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --shortcut -1 -o ${RO})
cmfilter_cli_case(NAME render.bad.tolerance-unreachable EXIT 3 STDERR "/surfaces/0/material/colormap: no table up to 4096 values x 1024 sigmas meets the tolerance 1e-06"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --tolerance 1e-6 -o ${RO})

# Microsurface materials (height-correlated colour, sec. 5.1): the bundled
# example at 32 x 24 (written beside the outputs with absolute paths) through
# each method that filters a microsurface; the image and its AOVs must be
# 32 x 24 with every value finite, the colours >= 0 (oiiotool --stats).
set(MICRO_SCENE ${SCB}/microsurface-small.json)
add_test(NAME cli.render.microsurface-scene
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/write_small_scene.py
                 ${EX}/plane-microsurface-sand-snow.json ${MICRO_SCENE} 32 24)
set_tests_properties(cli.render.microsurface-scene PROPERTIES FIXTURES_SETUP microsurface_scene LABELS cli)
set(CHECK_FINITE ${CMAKE_CURRENT_SOURCE_DIR}/check_finite_image.sh)
foreach(method naive gaussian gaussian-exact exact)
  set(MO ${OUT}/render-microsurface-${method})
  cmfilter_cli_case(NAME render.microsurface-${method} EXIT 0
                    STDOUT "32 x 24, ${method}, 1 ray\\(s\\) per pixel, [1-9][0-9]* pixels on a surface"
                    COMMAND ${CMF} render ${MICRO_SCENE} --method ${method} -o ${MO}.exr --aov ${MO})
  set_tests_properties(cli.render.microsurface-${method} PROPERTIES
                       FIXTURES_REQUIRED "cli_dirs;cli_fixtures;microsurface_scene"
                       FIXTURES_SETUP render_microsurface_${method})
  add_test(NAME cli.render.microsurface-${method}-finite
           COMMAND bash -c "bash $0 $1 $2.exr 32 24 --nonnegative && for f in $2.mean.exr $2.sigma.exr $2.lod.exr; do bash $0 $1 $f 32 24 || exit 1; done"
                   ${CHECK_FINITE} ${OIIOTOOL} ${MO})
  set_tests_properties(cli.render.microsurface-${method}-finite PROPERTIES
                       FIXTURES_REQUIRED render_microsurface_${method} LABELS cli)
endforeach()
# supersample ray traces the displaced plane: its image must be as finite.
cmfilter_cli_case(NAME render.microsurface-supersample EXIT 0
                  STDOUT "32 x 24, supersample, 4 ray\\(s\\) per pixel, [1-9][0-9]* pixels on a surface"
                  COMMAND ${CMF} render ${MICRO_SCENE} --method supersample --spp 4
                          -o ${OUT}/render-microsurface-supersample.exr)
set_tests_properties(cli.render.microsurface-supersample PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;microsurface_scene"
                     FIXTURES_SETUP render_microsurface_supersample)
add_test(NAME cli.render.microsurface-supersample-finite
         COMMAND bash ${CHECK_FINITE} ${OIIOTOOL} ${OUT}/render-microsurface-supersample.exr 32 24 --nonnegative)
set_tests_properties(cli.render.microsurface-supersample-finite PROPERTIES
                     FIXTURES_REQUIRED render_microsurface_supersample LABELS cli)
# --method auto on a microsurface: its cheapest one-ray method measured
# against exact on the view (render/microsurface_method_choice.h), then its
# fewest probes against --probes' (surface_probe_choice.h), printed and
# recorded; the recorded method and probes (with the tables fitted to the
# same tolerance) render the image auto wrote, pixel for pixel (idiff: no
# difference at all), and at 1 the method is not naive. (The choices'
# numbers are checked against whole renders in the unit tests.)
cmfilter_cli_case(NAME render.auto-microsurface-renders-its-choice EXIT 0
                  STDOUT "naive +worst.*<- chosen.*up to +[0-9]+ probes?, +worst.*<- chosen.*recorded [a-z-]+, [0-9]+ probes"
                  COMMAND bash -c "set -e -o pipefail && $0 render $1 --method auto --tolerance 1 -o $2/render-auto-ms.exr | tr '\\n' ' ' && m=$(oiiotool --info -v $2/render-auto-ms.exr | sed -n 's/.*cmfilter:microsurface_methods: \"0: \\(.*\\)\"/\\1/p') && n=$(oiiotool --info -v $2/render-auto-ms.exr | sed -n 's/.*cmfilter:surface_probes: \"0: \\(.*\\)\"/\\1/p') && echo recorded $m, $n probes && test -n \"$m\" && test -n \"$n\" && test \"$m\" != naive && $0 render $1 --method $m --probes $n --tolerance 1 -o $2/render-auto-ms-by.exr -q && idiff -fail 0 -failpercent 0 -warn 0 $2/render-auto-ms.exr $2/render-auto-ms-by.exr"
                          ${CMF} ${MICRO_SCENE} ${OUT})
set_tests_properties(cli.render.auto-microsurface-renders-its-choice
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;microsurface_scene")
# A bad microsurface names its key and writes nothing.
cmfilter_cli_case(NAME render.bad.microsurface-sigma-h EXIT 3
                  STDERR "microsurface-bad\\.json: /surfaces/0/material/microsurface/sigma_h: expected a number >= 0, got -0\\.008"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/microsurface-bad.json -o ${RO})

# Masking other than the two forms is refused before anything is written.
cmfilter_cli_case(NAME render.bad.masking EXIT 3
                  STDERR "--masking 'sideways' is unknown \\(expected uncorrelated or correlated\\)"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/microsurface-too-fine.json --masking sideways -o ${RO})
# So is a slope shading other than the two forms.
cmfilter_cli_case(NAME render.bad.slope-shading EXIT 3
                  STDERR "--slope-shading 'sideways' is unknown \\(expected uncorrelated or correlated\\)"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/slope-good.json --slope-shading sideways -o ${RO})
# A displacement image that is not square names the key, the file and its size.
cmfilter_cli_case(NAME render.bad.displacement-not-square EXIT 3
                  STDERR "displacement-not-square\\.json: /surfaces/0/material/displacement: displacement '.*narrow-band\\.png' is 256 x 1 texels \\(expected a square image"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/displacement-not-square.json -o ${RO})
# A microsurface whose traced tile would pass 4096 texels per side: the
# filtered methods render it, the ray-traced ones name the key and what fits.
cmfilter_cli_case(NAME render.bad.microsurface-too-fine EXIT 3
                  STDERR "microsurface-too-fine\\.json: /surfaces/0/material/microsurface: reference traces one tile .*a shorter tile or a longer min_wavelength fits.*resolution 8192"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/microsurface-too-fine.json --method reference -o ${RO})

# Slope-coloured and combined microsurface materials (secs. 5.2 and 6): a bad
# slope map or a missing combination names its key and writes nothing; a
# product of heights and slope vectors renders by a filtered method and by
# the ray-traced one, finite.
cmfilter_cli_case(NAME render.bad.slope-max-slope-on-steepness EXIT 3
                  STDERR "slope-bad-max-slope\\.json: /surfaces/0/material/slope_colormap/max_slope: applies only to a slope-vector map \\(\"by\": \"vector\"\\)"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/slope-bad-max-slope.json -o ${RO})
cmfilter_cli_case(NAME render.bad.slope-by EXIT 3
                  STDERR "slope-bad-by\\.json: /surfaces/0/material/slope_colormap/by: expected \"steepness\" or \"vector\", got \"aspect\""
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/slope-bad-by.json -o ${RO})
cmfilter_cli_case(NAME render.bad.slope-not-an-image EXIT 3
                  STDERR "slope-not-an-image\\.json: /surfaces/0/material/slope_colormap: .*good\\.json' is not an image OpenImageIO can read"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/slope-not-an-image.json -o ${RO})
cmfilter_cli_case(NAME render.bad.combine-missing EXIT 3
                  STDERR "combine-missing\\.json: /surfaces/0/material/combine: required with more than one of colormap, slope_colormap and base"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/combine-missing.json -o ${RO})
# Both correlations are render's defaults, and each can be turned off: the
# default render is the one with both named, pixel for pixel, and differs
# from each with one turned off.
set(DEFAULTS_OUT ${OUT}/render-defaults)
foreach(variant "defaults" "correlated;--masking;correlated;--slope-shading;correlated"
                "masking-off;--masking;uncorrelated" "shading-off;--slope-shading;uncorrelated")
  list(POP_FRONT variant name)
  set(options ${variant})
  cmfilter_cli_case(NAME render.defaults-${name} EXIT 0 STDOUT "gaussian"
                    COMMAND ${CMF} render ${SC}/slope-good.json --method gaussian ${options} -o ${DEFAULTS_OUT}-${name}.exr)
  set_tests_properties(cli.render.defaults-${name} PROPERTIES FIXTURES_SETUP render_defaults_${name})
endforeach()
cmfilter_cli_case(NAME render.defaults-are-correlated EXIT 0 STDOUT "\"max\": 0\\.0,"
                  COMMAND ${CMF} compare ${DEFAULTS_OUT}-defaults.exr ${DEFAULTS_OUT}-correlated.exr --json)
set_tests_properties(cli.render.defaults-are-correlated PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;cli_fixtures;render_defaults_defaults;render_defaults_correlated")
foreach(name masking-off shading-off)
  cmfilter_cli_case(NAME render.defaults-differ-${name} EXIT 0 STDOUT "\"mean\": 0\\.0*[1-9]|\"mean\": [1-9]"
                    COMMAND ${CMF} compare ${DEFAULTS_OUT}-defaults.exr ${DEFAULTS_OUT}-${name}.exr --json)
  set_tests_properties(cli.render.defaults-differ-${name} PROPERTIES
                       FIXTURES_REQUIRED "cli_dirs;cli_fixtures;render_defaults_defaults;render_defaults_${name}")
endforeach()
foreach(method gaussian supersample)
  set(SO ${OUT}/render-slope-${method}.exr)
  cmfilter_cli_case(NAME render.slope-${method} EXIT 0
                    STDOUT "24 x 16, ${method}, [0-9]+ ray\\(s\\) per pixel, [1-9][0-9]* pixels on a surface"
                    COMMAND ${CMF} render ${SC}/slope-good.json --method ${method} --spp 4 -o ${SO})
  set_tests_properties(cli.render.slope-${method} PROPERTIES FIXTURES_SETUP render_slope_${method})
  add_test(NAME cli.render.slope-${method}-finite COMMAND bash ${CHECK_FINITE} ${OIIOTOOL} ${SO} 24 16 --nonnegative)
  set_tests_properties(cli.render.slope-${method}-finite PROPERTIES FIXTURES_REQUIRED render_slope_${method} LABELS cli)
endforeach()

# --region x0,y0,x1,y1 (docs/farm.md): malformed, empty, outside the frame
# (also the frame --size gives) and a PNG output are refused, naming
# --region, the value and what is expected, and write nothing. Regions
# stitched into the whole frame: tests/cli/farm.cmake.
set(RR ${OUT}/render-bad-region.exr)
cmfilter_cli_case(NAME render.bad.region-malformed EXIT 3
                  STDERR "--region '1,2,3' is not a region \\(expected x0,y0,x1,y1: four integers >= 0, pixel coordinates of the whole frame, x0,y0 inclusive, x1,y1 exclusive\\)"
                  ABSENT ${RR} COMMAND ${CMF} render ${SC}/good.json --region 1,2,3 -o ${RR})
cmfilter_cli_case(NAME render.bad.region-not-numbers EXIT 3 STDERR "--region '0,0,8,x' is not a region"
                  ABSENT ${RR} COMMAND ${CMF} render ${SC}/good.json --region 0,0,8,x -o ${RR})
cmfilter_cli_case(NAME render.bad.region-negative EXIT 3 STDERR "--region '-4,0,8,8' is not a region"
                  ABSENT ${RR} COMMAND ${CMF} render ${SC}/good.json --region=-4,0,8,8 -o ${RR})
cmfilter_cli_case(NAME render.bad.region-empty EXIT 3
                  STDERR "--region 4,2,4,9 is empty \\(expected x0,y0 inclusive, x1,y1 exclusive, in the 32 x 18 frame: 0 <= x0 < x1 <= 32 and 0 <= y0 < y1 <= 18\\)"
                  ABSENT ${RR} COMMAND ${CMF} render ${SC}/good.json --region 4,2,4,9 -o ${RR})
cmfilter_cli_case(NAME render.bad.region-outside EXIT 3
                  STDERR "--region 16,0,33,18 lies outside the frame \\(expected x0,y0 inclusive, x1,y1 exclusive, in the 32 x 18 frame"
                  ABSENT ${RR} COMMAND ${CMF} render ${SC}/good.json --region 16,0,33,18 -o ${RR})
cmfilter_cli_case(NAME render.bad.region-outside-size EXIT 3
                  STDERR "--region 0,0,32,18 lies outside the frame \\(expected .* in the 16 x 9 frame"
                  ABSENT ${RR} COMMAND ${CMF} render ${SC}/good.json --size 16x9 --region 0,0,32,18 -o ${RR})
cmfilter_cli_case(NAME render.bad.region-png EXIT 3
                  STDERR "--region '0,0,8,8' needs an OpenEXR output \\(expected -o ending in \\.exr, whose data window places the region in the frame; got '.*render-bad-region\\.png'\\)"
                  ABSENT ${OUT}/render-bad-region.png
                  COMMAND ${CMF} render ${SC}/good.json --region 0,0,8,8 -o ${OUT}/render-bad-region.png)
cmfilter_cli_case(NAME render.bad.region-aov EXIT 3 STDERR "--region 0,0,8,19 lies outside the frame"
                  ABSENT ${RR} ${OUT}/render-bad-region-aov.mean.exr
                  COMMAND ${CMF} render ${SC}/good.json --region 0,0,8,19 -o ${RR} --aov ${OUT}/render-bad-region-aov)
# A region's summary: the region and its size within the frame.
cmfilter_cli_case(NAME render.region EXIT 0 STDOUT "region 3,2,19,11 \\(16 x 9\\) of 32 x 18, gaussian, 1 ray"
                  COMMAND ${CMF} render ${SC}/good.json --region 3,2,19,11 -o ${OUT}/render-region.exr)
# mixture on a noise driver: the footprints in the transition cut into
# squares (noise_sub_footprints.h); the most per axis is recorded, and with
# one square it is gaussian pixel for pixel (idiff: no difference at all).
cmfilter_cli_case(NAME render.mixture-noise-records EXIT 0
                  STDOUT "\"sub_footprints\": 4.*cmfilter:method: \"mixture\".*cmfilter:sub_footprints: 4"
                  COMMAND bash -c "set -o pipefail && ($0 render $1 --method mixture --sub-footprints 4 --json -o $2 && oiiotool --info -v $2) | tr '\\n' ' '"
                          ${CMF} ${SC}/good.json ${OUT}/render-mixture-noise.exr)
cmfilter_cli_case(NAME render.mixture-one-square-is-gaussian EXIT 0
                  COMMAND bash -c "$0 render $1 --method mixture --sub-footprints 1 -o $2/render-mixture-1.exr -q && $0 render $1 --method gaussian -o $2/render-mixture-g.exr -q && idiff -fail 0 -failpercent 0 -warn 0 $2/render-mixture-1.exr $2/render-mixture-g.exr"
                          ${CMF} ${SC}/good.json ${OUT})
cmfilter_cli_case(NAME render.bad.sub-footprints EXIT 3 STDERR "--sub-footprints 0 is out of range \\(expected 1 to 16\\)"
                  ABSENT ${RO} COMMAND ${CMF} render ${SC}/good.json --method mixture --sub-footprints 0 -o ${RO})
# --method auto on a noise surface: its fewest sub-footprints measured for
# the tolerance (at LOD 0 here), recorded; none meeting it is exit 3 with
# the closest named and nothing written.
cmfilter_cli_case(NAME render.auto-noise-records EXIT 0
                  STDOUT "surface 0: gaussian \\(one square\\).*cmfilter:noise_sub_footprints: \"0: 1\""
                  COMMAND bash -c "set -o pipefail && ($0 render $1 --method auto --tolerance 100 --measure-lods 0 -o $2 && oiiotool --info -v $2) | tr '\\n' ' '"
                          ${CMF} ${SCB}/noise-auto.json ${OUT}/render-auto-noise.exr)
# Without --measure-lods a noise is measured at the LODs its pixels reach.
# Straight down from height 2, 30 degrees over 32 pixels, 4 noise units (base
# periods of the gradient fBm) to a scene unit, one probe a pixel: every
# footprint is 4 * 2 * 2 tan(15 deg) / 32 = 0.134 base periods, LOD -2.90, so
# LODs -3 and -2; the sphere behind the camera is not measured.
cmfilter_cli_case(NAME render.auto-noise-view-lods EXIT 0
                  STDOUT "surface 0: .*at LOD -3, -2:\n"
                  STDERR "surface 1: no pixel sees it; its methods are not measured"
                  COMMAND ${CMF} render ${SCB}/noise-auto-down.json --method auto --tolerance 100 --probes 1
                          -o ${OUT}/render-auto-noise-down.exr)
cmfilter_cli_case(NAME render.bad.auto-noise-none-meets EXIT 3
                  STDERR "surface 0 \\(.*noise-auto\\.json\\): no number of sub-footprints meets --tolerance 0\\.1 \\(mean CIEDE2000 at every LOD 0 of its noise\\): the closest, up to [0-9]+ x [0-9]+ squares, is [0-9.]+ at LOD 0"
                  ABSENT ${RO} COMMAND ${CMF} render ${SCB}/noise-auto.json --method auto --tolerance 0.1 --measure-lods 0 -o ${RO})
