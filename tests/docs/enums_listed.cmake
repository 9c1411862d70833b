# SPDX-License-Identifier: BSL-1.0
# Fails unless docs/enums.md has a table for every enum the public headers declare: every
# `enum class NAME` under SOURCE/include/seawire outside detail/ (and outside a class's private
# part: stream_reader's state). The values of each listed enum are the generator's business
# (docs_enums_current).
file(GLOB_RECURSE headers "${SOURCE}/include/seawire/*.hpp")
file(READ "${SOURCE}/docs/enums.md" doc)
set(private_enums state)
set(missing "")
foreach(header IN LISTS headers)
  if(header MATCHES "/detail/")
    continue()
  endif()
  file(READ "${header}" text)
  string(REGEX MATCHALL "enum class [a-z_0-9]+" decls "${text}")
  foreach(decl IN LISTS decls)
    string(REPLACE "enum class " "" name "${decl}")
    list(FIND private_enums "${name}" private)
    if(NOT private EQUAL -1)
      continue()
    endif()
    string(FIND "${doc}" "::${name}`\n" at)
    if(at EQUAL -1)
      list(APPEND missing "${name} (${header})")
    endif()
  endforeach()
endforeach()
if(missing)
  message(FATAL_ERROR "docs/enums.md lists no table for: ${missing}. Add the enum to "
                      "tests/docs/enums_doc.cpp and regenerate docs/enums.md.")
endif()
message(STATUS "docs/enums.md lists every public enum")
