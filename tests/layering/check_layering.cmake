# Fails when a source file includes against the layering of README.md's layout table:
#  - <GL/...>, <EGL/...>, <GLFW/...>, <epoxy/...> or <glad/...> outside */gl/ folders;
#  - a project include ("folder/file.h", "folder/sub/file.h") of a library the including folder
#    may not depend on. No folder outside */gl/ may include a */gl/ folder (GL code is what
#    includes GL headers, directly or through a */gl/ header), except tools/, the executable.
# Usage: cmake -DROOT=<tree> -P check_layering.cmake
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_layering.cmake")
endif()

# folder -> folders it may include (besides itself).
set(allowed_config "")
set(allowed_display "config")
set(allowed_scenes "config")
set(allowed_input "config")
set(allowed_render "config;display;scenes")
set(allowed_walls "config;display;scenes;render")
set(allowed_display/gl "config;display;scenes;input;render")
set(allowed_walls/gl "config;display;scenes;render;walls;display/gl")
set(allowed_app "config;display;scenes;input;render;walls")
set(allowed_app/gl "config;display;scenes;input;render;walls;display/gl;walls/gl;app")
set(allowed_app/bench "config;display;scenes;input;render;walls;app")
set(allowed_app/bench/gl "config;display;scenes;input;render;walls;display/gl;walls/gl;app;app/gl;app/bench")
set(allowed_tools "config;display;scenes;input;render;walls;display/gl;walls/gl;app;app/gl;app/bench;app/bench/gl")
set(layers config display scenes input render walls display/gl walls/gl app app/gl app/bench app/bench/gl tools)

set(violations "")
foreach(layer IN LISTS layers)
  file(GLOB files LIST_DIRECTORIES false "${ROOT}/${layer}/*.h" "${ROOT}/${layer}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS includes)
      if(line MATCHES "<(GL|EGL|GLFW|epoxy|glad)/" AND NOT layer MATCHES "/gl$")
        list(APPEND violations "${layer}: ${f}: ${line} (GL/EGL/GLFW headers only in */gl/)")
      endif()
      if(line MATCHES "\"([a-z_/]+)/[^/\"]+\"")
        set(target "${CMAKE_MATCH_1}")
        if(NOT target STREQUAL layer AND target IN_LIST layers AND NOT target IN_LIST allowed_${layer})
          list(APPEND violations "${layer}: ${f}: ${line} (${layer} may include only: ${allowed_${layer}})")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
message(STATUS "layering: OK")
