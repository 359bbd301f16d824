# SPDX-License-Identifier: MIT
# Install rules and the exported CMake package: find_package(semhap) gives semhap::core and
# semhap::patterns to other people's tests. Only the public API's headers are installed.
include(CMakePackageConfigHelpers)

set(SEMHAP_PUBLIC_HEADERS
    patterns/loaderror.h patterns/waveform.h patterns/pattern.h patterns/voice.h
    patterns/patternlibrary.h
    core/contactframe.h core/actortable.h core/semanticevent.h core/deviceframe.h
    core/eventbuffer.h core/detector.h core/messagetracker.h core/forcedetector.h
    core/slipdetector.h core/contactframereader.h core/jsonlineswriter.h
    core/devicemodel.h core/routercontext.h core/routergraph.h core/router.h core/player.h
    core/pipeline.h core/statistics.h
    core/patternrender.h)

install(TARGETS semhap_patterns semhap_core EXPORT semhapTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${SEMHAP_PUBLIC_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/semhap)
install(EXPORT semhapTargets NAMESPACE semhap::
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/semhap)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/semhapConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/semhapConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/semhap)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/semhapConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/semhapConfig.cmake
    ${CMAKE_CURRENT_BINARY_DIR}/semhapConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/semhap)
