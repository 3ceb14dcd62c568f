include(CMakePackageConfigHelpers)
get_property(_libs GLOBAL PROPERTY FERRO_LIBRARIES)
install(TARGETS ${_libs} ferro_options EXPORT ferrodynTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ferro_hdf5 EXPORT ferrodynTargets)
foreach(_folder io numerics contact track vehicle fe_contact scenarios)
  # A folder with no public headers yet has no include/ in a clean clone (git keeps no empty dirs).
  if(EXISTS ${PROJECT_SOURCE_DIR}/${_folder}/include)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_folder}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()
install(EXPORT ferrodynTargets NAMESPACE ferro:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ferrodyn)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ferrodynConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ferrodynConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ferrodyn)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ferrodynConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ferrodynConfig.cmake ${PROJECT_BINARY_DIR}/ferrodynConfigVersion.cmake
        ${PROJECT_SOURCE_DIR}/cmake/FerroDependencies.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ferrodyn)
