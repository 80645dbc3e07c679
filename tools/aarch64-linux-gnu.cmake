# CMake toolchain for 64-bit Arm with Debian's cross compiler (g++-aarch64-linux-gnu);
# the programs run under qemu-user. Used by tools/cross_check_aarch64.sh, with
# SPINDRIFT_RENDER=OFF: the sim, spindrift-check and the sim's tests need only
# header-only libraries (glm, nlohmann-json, tinygltf), which the cross compiler finds
# in /usr/include after its own C library headers.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)
