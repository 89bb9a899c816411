# SPDX-License-Identifier: Apache-2.0
# A studio's OpenColorIO config (ACEScg working space, sRGB textures, roles,
# file rules; written by the test) end to end: bake, apply, render, compare.
add_test(NAME cli.studio-config
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_studio_config.sh ${CMF} ${LUTS}/terrain.png
                 ${FIX}/driver-37x23.png ${SC}/good.json ${OUT}/studio-config)
set_tests_properties(cli.studio-config PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures" LABELS cli
                     ENVIRONMENT "OCIO=")
