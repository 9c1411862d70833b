# SPDX-License-Identifier: BSL-1.0
# cmake -DBUILD_DIR=... -DPREFIX=... -DSOURCE_DIR=... [-DCONFIG=...] -P install.cmake
# Installs the build into a fresh PREFIX, then checks that every public header arrived.
foreach(var IN ITEMS BUILD_DIR PREFIX SOURCE_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "install.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${PREFIX}")
set(config_args "")
if(CONFIG)
  set(config_args --config "${CONFIG}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                        ${config_args} COMMAND_ERROR_IS_FATAL ANY)

file(GLOB_RECURSE source_headers RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/*.hpp")
file(GLOB_RECURSE installed_headers RELATIVE "${PREFIX}/include" "${PREFIX}/include/*")
list(SORT source_headers)
list(SORT installed_headers)
if(NOT source_headers STREQUAL installed_headers)
  message(FATAL_ERROR "installed headers differ from include/:\n"
                      "  source:    ${source_headers}\n  installed: ${installed_headers}")
endif()
list(LENGTH installed_headers count)
message(STATUS "installed ${count} headers into ${PREFIX}")
