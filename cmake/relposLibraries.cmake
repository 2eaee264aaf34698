# Imported targets for the C libraries relpos links that ship no CMake package of their own:
# relpos::GMP, relpos::MPFR, relpos::MPFI, relpos::FLINT. Used by the build (CMakeLists.txt) and by
# the installed relposConfig.cmake, so that the exported relpos::relpos names targets, not the
# absolute library paths of the machine it was built on.
foreach(_relpos_lib IN ITEMS GMP MPFR MPFI FLINT)
  if(TARGET relpos::${_relpos_lib})
    continue()
  endif()
  string(TOLOWER ${_relpos_lib} _relpos_name)
  if(_relpos_lib STREQUAL "FLINT")
    set(_relpos_header flint/fmpz_poly.h)
  else()
    set(_relpos_header ${_relpos_name}.h)
  endif()
  find_library(RELPOS_${_relpos_lib}_LIBRARY NAMES ${_relpos_name})
  find_path(RELPOS_${_relpos_lib}_INCLUDE_DIR NAMES ${_relpos_header})
  if(NOT RELPOS_${_relpos_lib}_LIBRARY OR NOT RELPOS_${_relpos_lib}_INCLUDE_DIR)
    set(_relpos_missing "${_relpos_lib} (lib${_relpos_name} and ${_relpos_header})")
    if(DEFINED CMAKE_FIND_PACKAGE_NAME)
      set(${CMAKE_FIND_PACKAGE_NAME}_FOUND FALSE)
      set(${CMAKE_FIND_PACKAGE_NAME}_NOT_FOUND_MESSAGE "relpos needs ${_relpos_missing}")
      return()
    endif()
    message(FATAL_ERROR "relpos needs ${_relpos_missing}")
  endif()
  add_library(relpos::${_relpos_lib} UNKNOWN IMPORTED)
  set_target_properties(relpos::${_relpos_lib} PROPERTIES
    IMPORTED_LOCATION "${RELPOS_${_relpos_lib}_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${RELPOS_${_relpos_lib}_INCLUDE_DIR}")
endforeach()
unset(_relpos_lib)
unset(_relpos_name)
unset(_relpos_header)
