# SPDX-License-Identifier: BSD-2-Clause
# What an object file's ABI is, read from the compiler's predefined macros,
# and whether a library built for one ABI links into code compiled for
# another. Used by the CMake build to describe itself, by an install's
# drdcConfig.cmake to choose and check a variant against the consumer's
# toolchain, and (its list DRDC_ABI_MACROS) by waf's install, which
# records each target's macros (waftools/library.py).

# The predefined macros that decide whether two objects link and run
# together: instruction set, architecture level, float ABI, sizes.
set(DRDC_ABI_MACROS
  __x86_64__ _WIN64 __arm__ __thumb__ __thumb2__ __ARM_ARCH
  __ARM_ARCH_PROFILE __ARM_FEATURE_DSP __ARM_PCS_VFP __riscv __riscv_xlen
  __riscv_float_abi_soft __riscv_float_abi_single __riscv_float_abi_double
  __riscv_compressed __riscv_mul __riscv_div __PPC__ _SOFT_FLOAT
  __AVR_ARCH__ __SIZEOF_INT__ __SIZEOF_LONG__ __SIZEOF_POINTER__
  __BYTE_ORDER__)

# drdc_abi_of(<out> <compiler> [flags...]): "NAME=VALUE;..." of the
# DRDC_ABI_MACROS the compiler defines with these flags.
function(drdc_abi_of out compiler)
  set(empty "${CMAKE_BINARY_DIR}/drdc_abi_empty.c")
  file(WRITE "${empty}" "")
  execute_process(COMMAND "${compiler}" ${ARGN} -dM -E "${empty}"
    OUTPUT_VARIABLE defines RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "drdc: ${compiler} ${ARGN} -dM -E failed: ${err}")
  endif()
  set(abi "")
  foreach(name IN LISTS DRDC_ABI_MACROS)
    if(defines MATCHES "#define ${name} ([^\n]*)")
      string(STRIP "${CMAKE_MATCH_1}" value)
      list(APPEND abi "${name}=${value}")
    endif()
  endforeach()
  set(${out} "${abi}" PARENT_SCOPE)
endfunction()

# _drdc_abi_get(<out> <abi> <name>): the value of one macro, "" if absent
function(_drdc_abi_get out abi name)
  set(value "")
  foreach(item IN LISTS abi)
    if(item MATCHES "^${name}=(.*)$")
      set(value "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

# drdc_abi_describe(<out> <abi>): the ABI in words, for messages
function(drdc_abi_describe out abi)
  foreach(n __x86_64__ _WIN64 __arm__ __ARM_ARCH __ARM_ARCH_PROFILE
      __ARM_PCS_VFP __thumb2__ __riscv __riscv_xlen __riscv_float_abi_soft
      __riscv_float_abi_single __riscv_compressed __PPC__ _SOFT_FLOAT
      __AVR_ARCH__)
    _drdc_abi_get(${n} "${abi}" ${n})
  endforeach()
  if(__arm__)
    # the profile's letter as its character code ('M' is 77)
    string(ASCII "${__ARM_ARCH_PROFILE}" profile)
    if(__ARM_PCS_VFP)
      set(fabi "hard-float ABI (floats in FPU registers)")
    else()
      set(fabi "soft-float ABI (floats in core registers: soft or softfp)")
    endif()
    if(__thumb2__)
      set(isa "Thumb-2")
    else()
      set(isa "Thumb-1")
    endif()
    set(text "Arm v${__ARM_ARCH}-${profile} ${isa}, ${fabi}")
  elseif(__riscv)
    if(__riscv_float_abi_soft)
      set(fabi "soft")
    elseif(__riscv_float_abi_single)
      set(fabi "single")
    else()
      set(fabi "double")
    endif()
    set(text "RISC-V rv${__riscv_xlen}, float ABI ${fabi}")
    if(__riscv_compressed)
      string(APPEND text ", compressed")
    endif()
  elseif(__PPC__)
    if(_SOFT_FLOAT)
      set(text "PowerPC, soft float")
    else()
      set(text "PowerPC, hard float")
    endif()
  elseif(__AVR_ARCH__)
    set(text "AVR architecture ${__AVR_ARCH__}")
  elseif(_WIN64)
    set(text "Windows x86-64")
  elseif(__x86_64__)
    set(text "x86-64")
  else()
    set(text "unknown (${abi})")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# drdc_abi_fits(<out> <why> <library abi> <consumer abi>): whether a
# library built for the first links into code compiled for the second
# and runs where it runs; <why> says why not.
function(drdc_abi_fits out why lib use)
  set(fits TRUE)
  set(reason "")
  # the same instruction set family and sizes
  foreach(n __x86_64__ _WIN64 __arm__ __riscv __PPC__ __AVR_ARCH__
      __SIZEOF_INT__ __SIZEOF_LONG__ __SIZEOF_POINTER__ __BYTE_ORDER__
      __ARM_ARCH_PROFILE __ARM_PCS_VFP __riscv_xlen __riscv_float_abi_soft
      __riscv_float_abi_single __riscv_float_abi_double _SOFT_FLOAT)
    _drdc_abi_get(a "${lib}" ${n})
    _drdc_abi_get(b "${use}" ${n})
    if(NOT "${a}" STREQUAL "${b}")
      set(fits FALSE)
      set(reason "${n} is '${a}' in the library, '${b}' here")
      break()
    endif()
  endforeach()
  if(fits)
    # the library's code must run on the consumer's core: no newer
    # architecture level, no instruction set extension it lacks
    _drdc_abi_get(a "${lib}" __ARM_ARCH)
    _drdc_abi_get(b "${use}" __ARM_ARCH)
    if(a AND b AND a GREATER b)
      set(fits FALSE)
      set(reason "the library needs Arm v${a}, this core is v${b}")
    endif()
    foreach(n __thumb2__ __ARM_FEATURE_DSP __riscv_compressed __riscv_mul
        __riscv_div)
      _drdc_abi_get(a "${lib}" ${n})
      _drdc_abi_get(b "${use}" ${n})
      if(a AND NOT b)
        set(fits FALSE)
        set(reason "the library uses ${n}, this core does not")
      endif()
    endforeach()
  endif()
  set(${out} ${fits} PARENT_SCOPE)
  set(${why} "${reason}" PARENT_SCOPE)
endfunction()
