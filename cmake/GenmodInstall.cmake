# `cmake --install` rules: libraries, headers and the genmod command produce a package that
# another CMake project finds with find_package(genmod) and links as genmod::kernel,
# genmod::tessellate, ... or the umbrella genmod::genmod.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GENMOD_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/genmod)

install(TARGETS genmod_kernel genmod_operators genmod_solvers genmod_tessellate genmod_procedural genmod_models genmod
  EXPORT genmodTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

if(TARGET genmod_app)
  install(TARGETS genmod_app RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

# Plain `include`, not CMAKE_INSTALL_INCLUDEDIR: the targets' usage requirements say
# $<INSTALL_INTERFACE:include>, and the two must agree.
foreach(dir kernel/include operators/include solvers/include tessellate/include procedural/include models/include include)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION include FILES_MATCHING PATTERN "*.hpp")
endforeach()

install(EXPORT genmodTargets NAMESPACE genmod:: DESTINATION ${GENMOD_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/genmodConfig.cmake.in
  ${PROJECT_BINARY_DIR}/genmodConfig.cmake
  INSTALL_DESTINATION ${GENMOD_INSTALL_CMAKEDIR})
# 0.x releases may break the API in any minor version.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/genmodConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/genmodConfig.cmake ${PROJECT_BINARY_DIR}/genmodConfigVersion.cmake
  DESTINATION ${GENMOD_INSTALL_CMAKEDIR})
