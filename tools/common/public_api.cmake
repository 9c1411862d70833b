# SPDX-License-Identifier: BSL-1.0
# The programs and examples are written against the public API only: no seawire detail
# namespace, no header under seawire/detail/. Run: cmake -DSOURCE_DIR=<root> -P public_api.cmake
file(GLOB_RECURSE sources "${SOURCE_DIR}/tools/*.cpp" "${SOURCE_DIR}/tools/*.hpp"
     "${SOURCE_DIR}/examples/*.cpp" "${SOURCE_DIR}/examples/*.hpp")
set(found "")
foreach(source IN LISTS sources)
  file(STRINGS "${source}" lines)
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    # Other libraries' detail namespaces (nlohmann::detail::exception) are theirs to expose.
    string(REGEX REPLACE "nlohmann::detail::" "" line "${line}")
    if(line MATCHES "detail::" OR line MATCHES "seawire/detail/")
      string(APPEND found "\n  ${source}:${n}: ${line}")
    endif()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "the programs or examples use seawire internals:${found}")
endif()
list(LENGTH sources count)
if(count EQUAL 0)
  message(FATAL_ERROR "no sources under ${SOURCE_DIR}/tools and ${SOURCE_DIR}/examples")
endif()
message(STATUS "${count} program and example sources use the public API only")
