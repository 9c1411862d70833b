# SPDX-License-Identifier: BSL-1.0
# Fails unless every message the public headers declare is in seawire/registry.hpp (LIST, a
# program iterating the registry, prints its addresses and PGNs) and described in
# docs/messages.md. A declared message is a sentence address given as a template argument
# (`sentence<"--RMC">`, `bluefin::nav_update<"CPNVG", ...>`) or a PGN struct (`pgn_info{127488,
# "engine_parameters_rapid", ...`: a PGN whose layout a field picks has a struct per layout),
# outside comments, in SOURCE/include/seawire. Every `static constexpr auto nmea =` or `n2k =`
# must be one of these forms (or the bluefin templates' `sentence<Address>`, declared through
# their instances), so that a message declared another way fails here rather than going unseen.
# EMULATOR, if not empty, runs a cross build's program.
file(GLOB_RECURSE headers "${SOURCE}/include/seawire/*.hpp")
list(FILTER headers EXCLUDE REGEX "/detail/")
set(declared "")
set(unknown_forms "")
foreach(header IN LISTS headers)
  file(READ "${header}" text)
  # Whole-text matches only: a line of C++ is no CMake list element (brackets and semicolons).
  string(REGEX REPLACE "//[^\n]*" "" text "${text}")
  string(REGEX MATCHALL "<\"[A-Z0-9-]+\"" addresses "${text}")
  foreach(a IN LISTS addresses)
    string(REGEX REPLACE "^<\"(.*)\"$" "\\1" a "${a}")
    list(APPEND declared "${a}")
  endforeach()
  # A PGN as "PGN <number> <struct>": a PGN may have several layouts, a struct each.
  string(REGEX MATCHALL "pgn_info{[0-9]+,[ \n]*\"[a-z0-9_]+\"" pgns "${text}")
  foreach(p IN LISTS pgns)
    string(REGEX REPLACE "^pgn_info{([0-9]+),[ \n]*\"([a-z0-9_]+)\"$" "PGN \\1 \\2" p "${p}")
    list(APPEND declared "${p}")
  endforeach()
  # Every description must name its address or PGN in one of those forms.
  string(REGEX MATCHALL "static constexpr auto (nmea|n2k) =" descriptions "${text}")
  string(REGEX REPLACE
         "static constexpr auto (nmea|n2k) =[^;]*(sentence<\"|sentence<Address>|pgn_info{)"
         "KNOWN_DESCRIPTION" marked "${text}")
  string(REGEX MATCHALL "KNOWN_DESCRIPTION" known "${marked}")
  list(LENGTH descriptions n_descriptions)
  list(LENGTH known n_known)
  if(NOT n_descriptions EQUAL n_known)
    list(APPEND unknown_forms "${header}")
  endif()
endforeach()
if(unknown_forms)
  message(FATAL_ERROR "a message description names its address or PGN in a form this check "
                      "does not read, in: ${unknown_forms}")
endif()
list(REMOVE_DUPLICATES declared)

separate_arguments(emulator UNIX_COMMAND "${EMULATOR}")
execute_process(COMMAND ${emulator} "${LIST}" OUTPUT_VARIABLE listed RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${LIST} failed: ${status}")
endif()
string(REPLACE "\n" ";" listed "${listed}")
file(READ "${SOURCE}/docs/messages.md" doc)

set(not_registered "")
set(not_documented "")
foreach(m IN LISTS declared)
  list(FIND listed "${m}" at)
  if(at EQUAL -1)
    list(APPEND not_registered "${m}")
  endif()
  if(m MATCHES "^PGN [0-9]+ ([a-z0-9_]+)$")
    string(FIND "${doc}" "\n`${CMAKE_MATCH_1}`: " at)  # a PGN struct's section
  else()
    string(FIND "${doc}" "\n### ${m}\n" at)
    if(at EQUAL -1)
      string(FIND "${doc}" "\n### ${m} " at)
    endif()
  endif()
  if(at EQUAL -1)
    list(APPEND not_documented "${m}")
  endif()
endforeach()
list(LENGTH declared n)
if(n LESS 40)
  message(FATAL_ERROR "found only ${n} declared messages: the scan of the headers is broken")
endif()
if(not_registered)
  message(FATAL_ERROR "declared but not in seawire/registry.hpp: ${not_registered}. Add each to "
                      "its role's set (or registry::pgns) there.")
endif()
if(not_documented)
  message(FATAL_ERROR "declared but not described in docs/messages.md: ${not_documented}. "
                      "Regenerate it with seawire_messages_doc.")
endif()
message(STATUS "all ${n} declared messages are in the registry and in docs/messages.md")
