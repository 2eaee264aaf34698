# Imported targets for the C libraries relpos links that ship no CMake package of their own:
# relpos::GMP, relpos::MPFR, relpos::MPFI, relpos::FLINT, and relpos::CGAL_headers (the CGAL and Boost
# headers, which relpos's public headers include: numbers.hpp uses CGAL::Gmpq and CGAL::Gmpz; the rest
# of CGAL is compiled into the library). Used by the build (CMakeLists.txt) and by the installed
# relposConfig.cmake, so that the exported targets name targets, not the absolute paths of the machine
# they were built on, and a consumer needs no find_package(CGAL).
macro(_relpos_missing what)
  if(DEFINED CMAKE_FIND_PACKAGE_NAME)
    set(${CMAKE_FIND_PACKAGE_NAME}_FOUND FALSE)
    set(${CMAKE_FIND_PACKAGE_NAME}_NOT_FOUND_MESSAGE "relpos needs ${what}")
    return()
  endif()
  message(FATAL_ERROR "relpos needs ${what}")
endmacro()

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
    _relpos_missing("${_relpos_lib} (lib${_relpos_name} and ${_relpos_header})")
  endif()
  add_library(relpos::${_relpos_lib} UNKNOWN IMPORTED)
  set_target_properties(relpos::${_relpos_lib} PROPERTIES
    IMPORTED_LOCATION "${RELPOS_${_relpos_lib}_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${RELPOS_${_relpos_lib}_INCLUDE_DIR}")
endforeach()

if(NOT TARGET relpos::CGAL_headers)
  find_path(RELPOS_CGAL_INCLUDE_DIR NAMES CGAL/Gmpq.h)
  find_path(RELPOS_BOOST_INCLUDE_DIR NAMES boost/version.hpp)
  if(NOT RELPOS_CGAL_INCLUDE_DIR OR NOT RELPOS_BOOST_INCLUDE_DIR)
    _relpos_missing("the CGAL and Boost headers (CGAL/Gmpq.h and boost/version.hpp)")
  endif()
  add_library(relpos::CGAL_headers INTERFACE IMPORTED)
  set_target_properties(relpos::CGAL_headers PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${RELPOS_CGAL_INCLUDE_DIR};${RELPOS_BOOST_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "relpos::MPFR;relpos::GMP")
endif()
unset(_relpos_lib)
unset(_relpos_name)
unset(_relpos_header)
