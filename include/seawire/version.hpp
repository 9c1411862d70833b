// SPDX-License-Identifier: BSL-1.0
#pragma once
// The one version number. CMakeLists.txt reads the three SEAWIRE_VERSION_* lines below, so keep
// them in the form `#define SEAWIRE_VERSION_<PART> <digits>`; everything else derives from them.

#include <string_view>

#define SEAWIRE_VERSION_MAJOR 0
#define SEAWIRE_VERSION_MINOR 1
#define SEAWIRE_VERSION_PATCH 0

// Two steps, so the arguments are expanded before they are turned into text.
#define SEAWIRE_DETAIL_VERSION_TEXT(major, minor, patch) #major "." #minor "." #patch
#define SEAWIRE_DETAIL_VERSION_EXPAND(major, minor, patch) \
  SEAWIRE_DETAIL_VERSION_TEXT(major, minor, patch)

/// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
#define SEAWIRE_VERSION_STRING \
  SEAWIRE_DETAIL_VERSION_EXPAND(SEAWIRE_VERSION_MAJOR, SEAWIRE_VERSION_MINOR, SEAWIRE_VERSION_PATCH)

/// One number for `#if`: MAJOR * 10000 + MINOR * 100 + PATCH (0.1.0 is 100).
#define SEAWIRE_VERSION \
  (SEAWIRE_VERSION_MAJOR * 10000 + SEAWIRE_VERSION_MINOR * 100 + SEAWIRE_VERSION_PATCH)

namespace seawire {

inline constexpr int version_major = SEAWIRE_VERSION_MAJOR;
inline constexpr int version_minor = SEAWIRE_VERSION_MINOR;
inline constexpr int version_patch = SEAWIRE_VERSION_PATCH;
/// The library's version as text, "MAJOR.MINOR.PATCH".
inline constexpr std::string_view version = SEAWIRE_VERSION_STRING;

}  // namespace seawire
