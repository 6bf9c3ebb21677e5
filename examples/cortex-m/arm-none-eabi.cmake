# SPDX-License-Identifier: BSD-2-Clause
# A CMake toolchain file for bare-metal Cortex-M with Debian's
# arm-none-eabi-gcc and newlib nano: the CPU and float ABI come from
# CORTEX_M_FLAGS (default a Cortex-M4F with the hard-float ABI), e.g.
#   -DCORTEX_M_FLAGS="-mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16"
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
# no start files for a test program: configure-time checks compile only
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CORTEX_M_FLAGS
    "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
    CACHE STRING "the CPU and float ABI flags of every file")
set(CMAKE_C_FLAGS_INIT "${CORTEX_M_FLAGS} --specs=nano.specs")
# (the compiler flags, nano.specs included, come to the link too)
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "--specs=nosys.specs -nostartfiles -Wl,--gc-sections")
