# SPDX-License-Identifier: BSD-2-Clause
# find_package(drdc) of an installed libdrdc-fx: one imported target per
# installed variant that fits this project's toolchain, drdc::<variant>
# (drdc::arm-cm4f, ...), and drdc::drdc for the one to use.
#
# Each variant (lib/cmake/drdc/drdc-<variant>.cmake, written by the
# install) records the ABI its library was built for, from its compiler's
# predefined macros. This file reads the same macros of this project's C
# compiler with CMAKE_C_FLAGS and DRDC_ABI_FLAGS (set it where the
# project passes its CPU flags otherwise) and compares: no flag is
# imposed on the project's own code.
#
#   find_package(drdc REQUIRED)                      drdc::drdc: the variant
#       built for exactly this ABI, or else the only one that fits
#   find_package(drdc REQUIRED COMPONENTS arm-cm4f)  that variant; a
#       variant that does not fit stops here, naming both ABIs
#   set(DRDC_VARIANT arm-cm4f) before find_package   the same
include("${CMAKE_CURRENT_LIST_DIR}/drdc_abi.cmake")
get_filename_component(_drdc_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.."
                       ABSOLUTE)

set(DRDC_INSTALLED_VARIANTS "")
file(GLOB _drdc_variant_files "${CMAKE_CURRENT_LIST_DIR}/drdc-*.cmake")
foreach(_drdc_file IN LISTS _drdc_variant_files)
  include("${_drdc_file}")
endforeach()

set(DRDC_ABI_FLAGS "" CACHE STRING
    "the project's CPU and float ABI flags, where not in CMAKE_C_FLAGS")
separate_arguments(_drdc_flags UNIX_COMMAND
                   "${CMAKE_C_FLAGS} ${DRDC_ABI_FLAGS}")
drdc_abi_of(_drdc_abi "${CMAKE_C_COMPILER}" ${_drdc_flags})
drdc_abi_describe(_drdc_here "${_drdc_abi}")

set(_drdc_fitting "")
set(_drdc_exact "")
foreach(_drdc_v IN LISTS DRDC_INSTALLED_VARIANTS)
  drdc_abi_fits(_drdc_fits _drdc_why "${DRDC_VARIANT_${_drdc_v}_ABI}"
                "${_drdc_abi}")
  set(DRDC_VARIANT_${_drdc_v}_FITS ${_drdc_fits})
  set(DRDC_VARIANT_${_drdc_v}_WHY "${_drdc_why}")
  if(_drdc_fits)
    list(APPEND _drdc_fitting ${_drdc_v})
    if("${DRDC_VARIANT_${_drdc_v}_ABI}" STREQUAL "${_drdc_abi}")
      list(APPEND _drdc_exact ${_drdc_v})
    endif()
    if(NOT TARGET drdc::${_drdc_v})
      add_library(drdc::${_drdc_v} STATIC IMPORTED)
      set_target_properties(drdc::${_drdc_v} PROPERTIES
        IMPORTED_LOCATION "${_drdc_prefix}/${DRDC_VARIANT_${_drdc_v}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${_drdc_prefix}/include"
        INTERFACE_LINK_LIBRARIES "${DRDC_VARIANT_${_drdc_v}_LIBS}")
    endif()
  endif()
endforeach()

# the variant asked for, else the exact one, else the only fitting one
set(_drdc_asked ${drdc_FIND_COMPONENTS})
if(DRDC_VARIANT)
  list(APPEND _drdc_asked ${DRDC_VARIANT})
endif()
set(_drdc_chosen "")
foreach(_drdc_v IN LISTS _drdc_asked)
  if(NOT _drdc_v IN_LIST DRDC_INSTALLED_VARIANTS)
    string(REPLACE ";" ", " _drdc_list "${DRDC_INSTALLED_VARIANTS}")
    set(drdc_FOUND FALSE)
    set(drdc_NOT_FOUND_MESSAGE
        "variant ${_drdc_v} is not installed in ${_drdc_prefix} (installed: ${_drdc_list})")
    return()
  endif()
  if(NOT DRDC_VARIANT_${_drdc_v}_FITS)
    drdc_abi_describe(_drdc_there "${DRDC_VARIANT_${_drdc_v}_ABI}")
    message(FATAL_ERROR
      "drdc: variant ${_drdc_v} was built for ${_drdc_there}; this project "
      "compiles for ${_drdc_here} (${CMAKE_C_COMPILER} ${_drdc_flags}): "
      "${DRDC_VARIANT_${_drdc_v}_WHY}. Install a variant built for this "
      "ABI, or build the library with this project (add_subdirectory).")
  endif()
  set(_drdc_chosen ${_drdc_v})
endforeach()
list(LENGTH _drdc_exact _drdc_n_exact)
list(LENGTH _drdc_fitting _drdc_n_fitting)
if(NOT _drdc_chosen AND _drdc_n_exact EQUAL 1)
  set(_drdc_chosen ${_drdc_exact})
elseif(NOT _drdc_chosen AND _drdc_n_fitting EQUAL 1)
  set(_drdc_chosen ${_drdc_fitting})
endif()
if(NOT _drdc_chosen AND NOT _drdc_fitting)
  set(_drdc_list "")
  foreach(_drdc_v IN LISTS DRDC_INSTALLED_VARIANTS)
    drdc_abi_describe(_drdc_there "${DRDC_VARIANT_${_drdc_v}_ABI}")
    string(APPEND _drdc_list "\n  ${_drdc_v}: ${_drdc_there}")
  endforeach()
  message(FATAL_ERROR
    "drdc: no installed variant fits this project's ${_drdc_here} "
    "(${CMAKE_C_COMPILER} ${_drdc_flags}); installed:${_drdc_list}")
endif()
if(_drdc_chosen AND NOT TARGET drdc::drdc)
  add_library(drdc::drdc INTERFACE IMPORTED)
  set_property(TARGET drdc::drdc PROPERTY
               INTERFACE_LINK_LIBRARIES drdc::${_drdc_chosen})
  message(STATUS "drdc: drdc::drdc is variant ${_drdc_chosen} "
                 "(${_drdc_here})")
elseif(NOT _drdc_chosen)
  string(REPLACE ";" ", " _drdc_list "${_drdc_fitting}")
  message(STATUS "drdc: several variants fit (${_drdc_list}): link the "
                 "one you want, drdc::<variant>, or set DRDC_VARIANT")
endif()
set(drdc_FOUND TRUE)
