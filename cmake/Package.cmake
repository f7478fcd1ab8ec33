# Installs curvetext as a package: the library, its headers (with the generated
# version.hpp), curvetextTargets.cmake + curvetextConfig.cmake +
# curvetextConfigVersion.cmake for find_package(curvetext CONFIG), and
# curvetext.pc for pkg-config. Included from lib/CMakeLists.txt.
include(CMakePackageConfigHelpers)

set(curvetext_cmake_dir "${CMAKE_INSTALL_LIBDIR}/cmake/curvetext")

install(TARGETS curvetext EXPORT curvetextTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/curvetext DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/lib/include/curvetext/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/curvetext)
install(EXPORT curvetextTargets NAMESPACE curvetext:: DESTINATION ${curvetext_cmake_dir})

# A static library needs its dependencies at the consumer's link; a shared one
# does not (the public headers include none of theirs).
if(BUILD_SHARED_LIBS)
  set(CURVETEXT_CONFIG_DEPENDENCIES "")
else()
  set(CURVETEXT_CONFIG_DEPENDENCIES "FREETYPE=freetype2;HARFBUZZ=harfbuzz;EGL=egl;GLESV2=glesv2;PNG=libpng;FRIBIDI=fribidi;UNIBREAK=libunibreak;THAI=libthai;FONTCONFIG=fontconfig;EXPAT=expat")
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/curvetextConfig.cmake.in
  ${PROJECT_BINARY_DIR}/curvetextConfig.cmake INSTALL_DESTINATION ${curvetext_cmake_dir})
# 0.x: a new minor version may break the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/curvetextConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/curvetextConfig.cmake ${PROJECT_BINARY_DIR}/curvetextConfigVersion.cmake
  DESTINATION ${curvetext_cmake_dir})

# pkg-config: the prefix relative to the .pc file's own folder
# (${pcfiledir}, which pkg-config and pkgconf set), and the paths relative to
# ${prefix} where they lie under it: right for `cmake --install --prefix`
# elsewhere than the configured prefix, and after the installed tree is moved.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(CURVETEXT_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH pc_to_prefix "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  set(CURVETEXT_PC_PREFIX "\${pcfiledir}/${pc_to_prefix}")
endif()
foreach(kind LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${kind}}")
    set(CURVETEXT_PC_${kind} "${CMAKE_INSTALL_${kind}}")
  else()
    set(CURVETEXT_PC_${kind} "\${prefix}/${CMAKE_INSTALL_${kind}}")
  endif()
endforeach()
set(CURVETEXT_PC_CFLAGS "")
if(BUILD_SHARED_LIBS)
  set(CURVETEXT_PC_CFLAGS " -DCURVETEXT_SHARED")
endif()
set(CURVETEXT_PC_LIBS_PRIVATE "")
foreach(lib IN LISTS CMAKE_DL_LIBS)
  string(APPEND CURVETEXT_PC_LIBS_PRIVATE " -l${lib}")
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/curvetext.pc.in ${PROJECT_BINARY_DIR}/curvetext.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/curvetext.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
