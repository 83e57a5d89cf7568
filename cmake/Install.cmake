# Install rules: the program, its man page and shell completions (both made
# by the program itself at build time, so new options appear without hand
# edits), the README and the licence; `cpack -G DEB` packs the same files.
include(GNUInstallDirs)

set(TERMSHADE_GENERATED ${CMAKE_BINARY_DIR}/generated)
set(TERMSHADE_GENERATED_FILES)
foreach(kind IN ITEMS man bash zsh fish)
  set(file_man termshade.1)
  set(file_bash termshade.bash)
  set(file_zsh _termshade)
  set(file_fish termshade.fish)
  set(output ${TERMSHADE_GENERATED}/${file_${kind}})
  add_custom_command(
    OUTPUT ${output}
    COMMAND termshade --generate ${kind} > ${output}.part
    COMMAND ${CMAKE_COMMAND} -E rename ${output}.part ${output}
    DEPENDS termshade termshade_assimp
    COMMENT "Generating ${file_${kind}}")
  list(APPEND TERMSHADE_GENERATED_FILES ${output})
endforeach()
add_custom_target(termshade_docs ALL DEPENDS ${TERMSHADE_GENERATED_FILES})

install(TARGETS termshade RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The Assimp import module and the import helper that runs it, where the
# program looks for them (src/io/import/OwnFile.h).
install(TARGETS termshade_assimp LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/termshade)
install(TARGETS termshade_import RUNTIME DESTINATION ${CMAKE_INSTALL_LIBDIR}/termshade)
install(FILES ${TERMSHADE_GENERATED}/termshade.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${TERMSHADE_GENERATED}/termshade.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME termshade)
install(FILES ${TERMSHADE_GENERATED}/_termshade
        DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
install(FILES ${TERMSHADE_GENERATED}/termshade.fish
        DESTINATION ${CMAKE_INSTALL_DATADIR}/fish/vendor_completions.d)
install(FILES README.md CONTRIBUTING.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
# The pages README.md links to, so its links hold in the installed copy too.
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md" PATTERN "*.svg" PATTERN "*.png" PATTERN "*.csv")

# cpack -G DEB (run in the build folder) makes termshade_VERSION_ARCH.deb.
set(CPACK_PACKAGE_NAME termshade)
set(CPACK_PACKAGE_CONTACT "termshade authors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "shaded 3D polygon models in a terminal")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
