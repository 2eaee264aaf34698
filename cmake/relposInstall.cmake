# Install rules: the libraries, their public headers, the relpos CLI, the CMake package
# (relposConfig.cmake, relposConfigVersion.cmake, relposTargets.cmake exporting relpos::relpos and
# relpos::relpos_shared) and relpos.pc for pkg-config (doc/install.md). Included from the top-level
# CMakeLists.txt.
include(CMakePackageConfigHelpers)

set(RELPOS_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/relpos" CACHE STRING
    "Where relposConfig.cmake is installed (relative to the prefix)")

install(TARGETS ${RELPOS_LIBRARY_TARGETS} EXPORT relposTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Every header left in include/relpos/ is public (private ones live next to the sources).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/relpos DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/include/relpos/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/relpos)
install(TARGETS relpos_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(EXPORT relposTargets NAMESPACE relpos:: DESTINATION ${RELPOS_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/relposConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/relposConfig.cmake
                              INSTALL_DESTINATION ${RELPOS_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/relposConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/relposConfig.cmake ${PROJECT_BINARY_DIR}/relposConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/relposLibraries.cmake
        DESTINATION ${RELPOS_INSTALL_CMAKEDIR})

# pkg-config: paths relative to ${prefix} when the install dirs are relative, so that
# `cmake --install build --prefix DIR` gives a relpos.pc that is right for DIR.
foreach(_dir IN ITEMS LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${_dir}}")
    set(RELPOS_PC_${_dir} "${CMAKE_INSTALL_${_dir}}")
  else()
    set(RELPOS_PC_${_dir} "\${prefix}/${CMAKE_INSTALL_${_dir}}")
  endif()
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/relpos.pc.in ${PROJECT_BINARY_DIR}/relpos.pc.in.configured @ONLY)
# ${prefix} is written at install time (cmake --install --prefix may differ from CMAKE_INSTALL_PREFIX).
install(CODE "
  file(READ \"${PROJECT_BINARY_DIR}/relpos.pc.in.configured\" _pc)
  string(REGEX REPLACE \"^prefix=[^\\n]*\" \"prefix=\${CMAKE_INSTALL_PREFIX}\" _pc \"\${_pc}\")
  file(WRITE \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig/relpos.pc\" \"\${_pc}\")
  message(STATUS \"Installing: \$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig/relpos.pc\")
")

# The package test: install into a temporary prefix, build a consumer with find_package and with
# pkg-config (tests/package/check_package.sh). Not in sanitizer builds (the consumers are not
# instrumented).
if(RELPOS_BUILD_TESTS AND BUILD_TESTING AND NOT RELPOS_SANITIZE)
  add_test(NAME package
           COMMAND bash ${PROJECT_SOURCE_DIR}/tests/package/check_package.sh ${PROJECT_BINARY_DIR}
                   ${PROJECT_SOURCE_DIR}/tests/package/consumer ${CMAKE_COMMAND} ${RELPOS_BUILD_SHARED})
  set_tests_properties(package PROPERTIES LABELS package TIMEOUT 600 COST 30)  # compiles: started early
endif()
