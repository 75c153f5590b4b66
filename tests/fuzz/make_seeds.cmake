# Build-time seed corpora for the fuzz targets, from the repository's own
# scene files (nothing downloaded): every scenes/**/*.toml as it is for the
# scene reader, and its keys as `section.key=value` lines for the --set
# parser. Run with -D SOURCE_DIR=... -D SCENE_SEEDS=... -D SET_SEEDS=...
file(GLOB_RECURSE scene_files "${SOURCE_DIR}/scenes/*.toml")
file(REMOVE_RECURSE "${SCENE_SEEDS}" "${SET_SEEDS}")
file(MAKE_DIRECTORY "${SCENE_SEEDS}" "${SET_SEEDS}")
foreach(scene_file IN LISTS scene_files)
  file(RELATIVE_PATH name "${SOURCE_DIR}/scenes" "${scene_file}")
  string(REPLACE "/" "_" name "${name}")
  configure_file("${scene_file}" "${SCENE_SEEDS}/${name}" COPYONLY)
  file(STRINGS "${scene_file}" lines)
  set(section "")
  set(assignments "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*\\[([A-Za-z_]+)\\]")
      set(section "${CMAKE_MATCH_1}")
    elseif(section AND line MATCHES "^[ \t]*([A-Za-z_]+)[ \t]*=[ \t]*(.*)$")
      set(key "${CMAKE_MATCH_1}")
      set(value "${CMAKE_MATCH_2}")
      if(value MATCHES "^(\"[^\"]*\")")  # a quoted text: up to its closing quote
        set(value "${CMAKE_MATCH_1}")
      else()  # a number or word: up to a comment
        string(REGEX REPLACE "[ \t]*#.*$" "" value "${value}")
      endif()
      string(STRIP "${value}" value)
      string(APPEND assignments "${section}.${key}=${value}\n")
    endif()
  endforeach()
  if(assignments)
    file(WRITE "${SET_SEEDS}/${name}.set" "${assignments}")
  endif()
endforeach()
