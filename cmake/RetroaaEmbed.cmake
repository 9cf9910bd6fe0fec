# retroaa_embed(target namespace root files...): embeds text files into a generated source of
# `target` (`namespace::embeddedFiles()`, keyed by path relative to `root`); the target rebuilds when
# any of them changes. Used by the plugin (shaders, presets) and the host (shaders, scenes).
set(RETROAA_EMBED_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/EmbedFiles.cmake")

function(retroaa_embed target namespace root)
  set(files ${ARGN})
  string(JOIN "|" joined ${files})  # a CMake list would split into separate command arguments
  string(REPLACE "::" "_" suffix "${namespace}")
  set(output "${CMAKE_CURRENT_BINARY_DIR}/${target}_${suffix}_embedded.cpp")
  add_custom_command(
    OUTPUT "${output}"
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DNAMESPACE=${namespace} -DROOT=${root}
            "-DFILES=${joined}" -P "${RETROAA_EMBED_SCRIPT}"
    DEPENDS ${files} "${RETROAA_EMBED_SCRIPT}"
    COMMENT "Embedding ${namespace} files"
    VERBATIM)
  target_sources(${target} PRIVATE "${output}")
endfunction()
