# SPDX-License-Identifier: BSL-1.0
# Fails when docs/api.md names what the headers do not declare: CHECKER (seawire_api_names)
# checks every identifier and file the page names and writes OUT, a using-declaration for each
# name the page qualifies by a seawire namespace, which COMPILER then compiles. EMULATOR, if not
# empty, runs a cross build's CHECKER (QEMU).
get_filename_component(out_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")
separate_arguments(emulator UNIX_COMMAND "${EMULATOR}")
execute_process(COMMAND ${emulator} "${CHECKER}" "${SOURCE}" "${OUT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "docs/api.md names what no header declares (above)")
endif()
execute_process(COMMAND "${COMPILER}" -std=c++20 -fsyntax-only "-I${SOURCE}/include" "${OUT}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "a name docs/api.md qualifies is not in that namespace (above)")
endif()
message(STATUS "docs/api.md names only what the headers declare")
