# SPDX-License-Identifier: BSL-1.0
# As aarch64-linux-gnu.cmake, with Clang targeting 64-bit ARM (it uses the same cross libraries,
# linker and QEMU):
#   apt-get install clang g++-aarch64-linux-gnu qemu-user
#   cmake -B build/aarch64-clang \
#     -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu-clang.cmake ...
include("${CMAKE_CURRENT_LIST_DIR}/aarch64-linux-gnu.cmake")
set(CMAKE_C_COMPILER clang)
set(CMAKE_C_COMPILER_TARGET aarch64-linux-gnu)
set(CMAKE_CXX_COMPILER clang++)
set(CMAKE_CXX_COMPILER_TARGET aarch64-linux-gnu)
