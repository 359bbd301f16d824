# SPDX-License-Identifier: MIT
# Install rules and the exported CMake package: find_package(semhap) gives semhap::core and
# semhap::patterns (with semhap::base under them) to other people's tests. Only the public API's headers are installed.
include(CMakePackageConfigHelpers)

set(SEMHAP_PUBLIC_HEADERS
    base/loaderror.h patterns/waveform.h patterns/pattern.h patterns/voice.h
    patterns/patternlibrary.h patterns/paramspec.h
    core/contactframe.h core/framesignals.h core/nametable.h core/actortable.h
    core/semanticevent.h core/deviceframe.h
    core/eventbuffer.h core/detector.h core/messagetracker.h core/forcedetector.h
    core/slipdetector.h core/contactframeparser.h core/contactframereader.h
    core/jsonlineswriter.h
    core/actuator.h core/devicemodel.h core/routercontext.h core/routergraph.h
    core/routernodetype.h
    core/router.h core/player.h
    core/pipeline.h core/nodeactivity.h core/sinklist.h core/statistics.h
    core/patternrender.h)

install(TARGETS semhap_base semhap_patterns semhap_core EXPORT semhapTargets
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

# The desktop package: binaries and the project's shared libraries (semhap::core and
# semhap::patterns above, found through the install RPATH), a desktop entry, its icon,
# AppStream metadata, man pages, bash completion, and `cpack` turns the tree into a .deb
# (dpkg-shlibdeps finds the libraries' packages).
set(semhap_desktop ${CMAKE_CURRENT_LIST_DIR}/../resources/desktop)
if(SEMHAP_BUILD_STUDIO)
    install(FILES ${semhap_desktop}/org.semhap.studio.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
    install(FILES ${semhap_desktop}/org.semhap.studio.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
    install(FILES ${semhap_desktop}/org.semhap.studio.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
endif()
install(FILES ${semhap_desktop}/semhap.bash-completion
    DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME semhap)
install(FILES ${semhap_desktop}/semhap.bash-completion
    DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME semhap-studio)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/../resources/traces/demo.jsonl
    DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)
# The manual and the reference pages with their pictures, and the READMEs they link to, laid
# out as in the sources, so that every link between them works where they are installed
# (tests/package checks): the studio's Help → Documentation opens docs/studio.md.
install(DIRECTORY ${CMAKE_CURRENT_LIST_DIR}/../docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
    FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
# Every module's README is taken, so that a new module's is installed with it.
file(GLOB module_readmes RELATIVE ${CMAKE_CURRENT_LIST_DIR}/.. ${CMAKE_CURRENT_LIST_DIR}/../*/README.md)
foreach(readme README.md ${module_readmes} devices/PROTOCOL.md tests/bench/README.md)
    get_filename_component(folder ${readme} DIRECTORY)
    install(FILES ${CMAKE_CURRENT_LIST_DIR}/../${readme}
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/${folder})
endforeach()

# Man pages from the programs' own --help (help2man), so they list every option there is.
find_program(HELP2MAN help2man)
if(HELP2MAN AND NOT SEMHAP_SANITIZE)
    set(man_dir ${CMAKE_BINARY_DIR}/man)
    add_custom_command(OUTPUT ${man_dir}/semhap.1
        COMMAND ${CMAKE_COMMAND} -E make_directory ${man_dir}
        COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:semhap>
                -DOUTPUT=${man_dir}/semhap.h2m
                -P ${CMAKE_CURRENT_LIST_DIR}/SemhapManInclude.cmake
        COMMAND ${HELP2MAN} --no-info --no-discard-stderr --section=1
                "--name=semantic haptic feedback, headless: detectors, router, patterns, simulation and sessions"
                --include=${man_dir}/semhap.h2m
                --output=${man_dir}/semhap.1 $<TARGET_FILE:semhap>
        DEPENDS semhap ${CMAKE_CURRENT_LIST_DIR}/SemhapManInclude.cmake
        COMMENT "Writing the man page of semhap" VERBATIM)
    set(man_pages ${man_dir}/semhap.1)
    if(TARGET semhap-studio)
        file(WRITE ${man_dir}/semhap-studio.h2m
            "[SEE ALSO]\n\\fBsemhap\\fR(1)\n")
        add_custom_command(OUTPUT ${man_dir}/semhap-studio.1
            COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen
                    ${HELP2MAN} --no-info --section=1
                    "--name=the studio for semantic haptic feedback in robot teleoperation"
                    --include=${man_dir}/semhap-studio.h2m
                    --output=${man_dir}/semhap-studio.1 $<TARGET_FILE:semhap-studio>
            DEPENDS semhap-studio
            COMMENT "Writing the man page of semhap-studio" VERBATIM)
        list(APPEND man_pages ${man_dir}/semhap-studio.1)
    endif()
    add_custom_target(semhap_man_pages ALL DEPENDS ${man_pages})
    install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME semhap)
set(CPACK_PACKAGE_VENDOR semhap)
set(CPACK_PACKAGE_CONTACT "semhap developers <semhap@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "semhap turns fingertip contact forces into semantic haptic messages (a stable grasp, a\n\
break or slip warning) and plays them as patterns on pneumatic or vibrotactile\n\
wristbands. This package has the studio (semhap-studio: simulation, live plots, router\n\
node editor, waveform designer with audition, sessions) and the headless command line\n\
(semhap), with the MuJoCo scenes of the paper's tasks.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_BINARY_DIR}/patterns
    ${CMAKE_BINARY_DIR}/core ${CMAKE_BINARY_DIR}/sim ${CMAKE_BINARY_DIR}/devices)
# Loaded as plugins, which dpkg-shlibdeps cannot see: sessions need SQLite, windows a
# platform plugin.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6sql6-sqlite, qt6-qpa-plugins")
# Qt's own words (dialog buttons, file dialogs) in German.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri, qt6-translations-l10n")
include(CPack)
