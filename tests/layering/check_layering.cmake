# Fails when a source file includes against the layering of docs/architecture.md's layout table:
#  - <GL/...>, <EGL/...>, <GLFW/...>, <epoxy/...> or <glad/...> outside */gl/ folders (in tests
#    too: tests/support/gl/ holds the GL test support);
#  - a project include ("folder/file.h", "folder/sub/file.h") of a library the including folder
#    may not depend on. No folder outside */gl/ may include a */gl/ folder (GL code is what
#    includes GL headers, directly or through a */gl/ header), except tools/, the executable;
#  - code in a */gl/ folder that needs no GL: every header/source pair (files of one name) there
#    must include a GL header or another */gl/ header. Pure logic belongs in the folder above,
#    where it builds and is unit-tested without a context. The one exception is listed below.
# Usage: cmake -DROOT=<tree> -P check_layering.cmake
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_layering.cmake")
endif()

# folder -> folders it may include (besides itself).
set(allowed_config "")
set(allowed_display "config")
set(allowed_scenes "config")
set(allowed_metrics "config;scenes")
set(allowed_input "config")
set(allowed_render "config;display;scenes")
set(allowed_walls "config;display;scenes;render")
set(allowed_hierarchy "config;display;scenes")
set(allowed_walkthrough "config;display;scenes;walls;hierarchy")
set(allowed_display/gl "config;display;scenes;input")
set(allowed_render/gl "config;display;scenes;render;display/gl")
set(allowed_walls/gl "config;display;scenes;render;walls;display/gl;render/gl")
set(allowed_hierarchy/gl "config;display;scenes;metrics;render;walls;hierarchy;display/gl;render/gl;walls/gl")
set(allowed_walkthrough/gl "config;display;scenes;render;walls;hierarchy;walkthrough;display/gl;render/gl;walls/gl;hierarchy/gl")
set(allowed_app "config;display;scenes;metrics;input;render;walls;hierarchy;walkthrough")
set(allowed_app/gl "config;display;scenes;metrics;input;render;walls;hierarchy;walkthrough;display/gl;render/gl;walls/gl;hierarchy/gl;walkthrough/gl;app")
set(allowed_app/bench "config;display;scenes;metrics;input;render;walls;hierarchy;walkthrough;app")
set(allowed_app/bench/gl "config;display;scenes;metrics;input;render;walls;hierarchy;walkthrough;display/gl;render/gl;walls/gl;hierarchy/gl;walkthrough/gl;app;app/gl;app/bench")
set(allowed_tools "config;display;scenes;metrics;input;render;walls;hierarchy;walkthrough;display/gl;render/gl;walls/gl;hierarchy/gl;walkthrough/gl;app;app/gl;app/bench;app/bench/gl")
set(layers config display scenes metrics input render walls hierarchy walkthrough display/gl render/gl walls/gl hierarchy/gl walkthrough/gl app app/gl app/bench app/bench/gl tools)

# */gl/ files that need no GL header yet are GL code, with the reason.
set(gl_without_gl_headers "render/gl/scene_shaders")  # GLSL sources and GL's indirect-command layout

set(violations "")
foreach(layer IN LISTS layers)
  file(GLOB files LIST_DIRECTORIES false "${ROOT}/${layer}/*.h" "${ROOT}/${layer}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS includes)
      if(line MATCHES "<(GL|EGL|GLFW|epoxy|glad)/" AND NOT layer MATCHES "/gl$")
        list(APPEND violations "${layer}: ${f}: ${line} (GL/EGL/GLFW headers only in */gl/)")
      endif()
      if(layer MATCHES "/gl$")
        get_filename_component(stem "${f}" NAME_WE)
        if(line MATCHES "<(GL|EGL|GLFW|epoxy|glad)/")
          set(uses_gl_${stem} TRUE)
        elseif(line MATCHES "\"[a-z_/]+/gl/([a-z_0-9]+)\\.h\"" AND NOT CMAKE_MATCH_1 STREQUAL stem)
          set(uses_gl_${stem} TRUE)
        endif()
      endif()
      if(line MATCHES "\"([a-z_/]+)/[^/\"]+\"")
        set(target "${CMAKE_MATCH_1}")
        if(NOT target STREQUAL layer AND target IN_LIST layers AND NOT target IN_LIST allowed_${layer})
          list(APPEND violations "${layer}: ${f}: ${line} (${layer} may include only: ${allowed_${layer}})")
        endif()
      endif()
    endforeach()
  endforeach()
  if(layer MATCHES "/gl$")
    foreach(f IN LISTS files)
      get_filename_component(stem "${f}" NAME_WE)
      if(NOT uses_gl_${stem} AND NOT "${layer}/${stem}" IN_LIST gl_without_gl_headers)
        list(APPEND violations "${layer}: ${f}: includes no GL header and no other */gl/ header "
                               "(GL-free code belongs outside */gl/)")
      endif()
    endforeach()
    foreach(f IN LISTS files)
      get_filename_component(stem "${f}" NAME_WE)
      unset(uses_gl_${stem})
    endforeach()
  endif()
endforeach()

# Tests: GL headers only in a gl/ folder of tests/ (tests/support/gl/, whose
# tests/support/gl/gl_test_support.h the other GL tests call instead, as they call the */gl/
# libraries).
file(GLOB_RECURSE test_files LIST_DIRECTORIES false "${ROOT}/tests/*.h" "${ROOT}/tests/*.cpp")
foreach(f IN LISTS test_files)
  file(RELATIVE_PATH rel "${ROOT}" "${f}")
  if(rel MATCHES "^tests/(.+/)?gl/")
    continue()
  endif()
  file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include")
  foreach(line IN LISTS includes)
    if(line MATCHES "<(GL|EGL|GLFW|epoxy|glad)/")
      list(APPEND violations "tests: ${rel}: ${line} (GL/EGL/GLFW headers only in gl/ folders)")
    endif()
  endforeach()
endforeach()

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
message(STATUS "layering: OK")
