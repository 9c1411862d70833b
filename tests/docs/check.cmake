# SPDX-License-Identifier: BSL-1.0
# Runs GENERATOR into OUT and fails unless OUT is byte for byte the COMMITTED file. EMULATOR, if
# not empty, is the command line that runs a cross build's program (QEMU).
get_filename_component(out_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")
separate_arguments(emulator UNIX_COMMAND "${EMULATOR}")
execute_process(COMMAND ${emulator} "${GENERATOR}" OUTPUT_FILE "${OUT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed: ${status}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUT}" "${COMMITTED}"
                RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "${COMMITTED} is out of date: the descriptions now generate ${OUT}. "
                      "Regenerate it: ${GENERATOR} > ${COMMITTED}")
endif()
message(STATUS "${COMMITTED} is what the descriptions generate")
