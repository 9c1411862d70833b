# SPDX-License-Identifier: BSL-1.0
# Settings for seawire's own targets: tests, examples, benchmarks, fuzzers. Only the top-level
# build includes this file, and nothing here touches seawire::seawire, so none of it reaches a
# project that uses the library.
include_guard(GLOBAL)

# seawire_dev_target(<target> [NO_SANITIZE])
#   Warnings (errors with SEAWIRE_WERROR) and, with SEAWIRE_SANITIZE, ASan + UBSan that stop at
#   the first report. NO_SANITIZE is for benchmarks, whose numbers sanitizers would distort.
function(seawire_dev_target tgt)
  cmake_parse_arguments(PARSE_ARGV 1 arg "NO_SANITIZE" "" "")
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${tgt} PRIVATE -Wall -Wextra -Wconversion -Wsign-conversion -Wshadow
                                          -Wpedantic)
    if(SEAWIRE_WERROR)
      target_compile_options(${tgt} PRIVATE -Werror)
    endif()
    if(SEAWIRE_SANITIZE AND NOT arg_NO_SANITIZE)
      set(sanitize -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
      target_compile_options(${tgt} PRIVATE ${sanitize})
      target_link_options(${tgt} PRIVATE ${sanitize})
    endif()
  elseif(MSVC)
    target_compile_options(${tgt} PRIVATE /W4 /permissive- $<$<BOOL:${SEAWIRE_WERROR}>:/WX>)
  endif()
endfunction()

# seawire_link_fmt(<target>)
#   Links {fmt} when it was found and tells the code through SEAWIRE_HAS_FMT (0 or 1), so a test
#   or example that prints with fmt can still be built, minus that part, where fmt is missing.
function(seawire_link_fmt tgt)
  if(fmt_FOUND)
    target_link_libraries(${tgt} PRIVATE fmt::fmt)
    target_compile_definitions(${tgt} PRIVATE SEAWIRE_HAS_FMT=1)
  else()
    target_compile_definitions(${tgt} PRIVATE SEAWIRE_HAS_FMT=0)
  endif()
endfunction()
