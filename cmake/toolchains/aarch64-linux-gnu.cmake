# SPDX-License-Identifier: BSL-1.0
# Cross-compiling for 64-bit ARM Linux (Raspberry Pi 3/4/5, Jetson) with Debian's cross compiler,
# running the tests under user-mode QEMU:
#   apt-get install g++-aarch64-linux-gnu qemu-user
#   cmake -B build/aarch64 -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake \
#     -DBUILD_TESTING=ON -DCMAKE_DISABLE_FIND_PACKAGE_fmt=ON
#   cmake --build build/aarch64 -j2 && ctest --test-dir build/aarch64
# Header-only packages (Catch2, nlohmann-json) are taken from the build machine; a compiled one
# ({fmt}) would be the build machine's, so leave it out as above.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# The target's libraries are found under /usr/aarch64-linux-gnu, the build machine's programs on
# its PATH.
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
# ctest and the tests that start a test program run it through QEMU, with the target's loader
# and libraries.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)
