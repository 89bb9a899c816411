// SPDX-License-Identifier: Apache-2.0
// The OpenColorIO config compiled into libcmfilter (source: lib/ocio/config.ocio).
#pragma once

namespace cmfilter {
const char* builtin_ocio_config_text();
}  // namespace cmfilter
