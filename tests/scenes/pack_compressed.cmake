# Writes compressed copies of a few shared models for the compressed-glTF tests (a CTest
# fixture): cmake -DREAL=<scenes-real> -DOUT=<folder> -P pack_compressed.cmake
#
# Per model NAME, with Debian's gltfpack: NAME-q.glb (quantized, KHR_mesh_quantization),
# NAME-c.glb and NAME-cc.glb (EXT_meshopt_compression, -c and -cc), NAME-noq.glb,
# NAME-c-noq.glb and NAME-cc-noq.glb (the same without quantization), and NAME-cc.gltf (text,
# with a .bin, written beside a copy of the source so that its image URIs resolve); with
# Debian's draco_transcoder: NAME-draco.glb (KHR_draco_mesh_compression).
#
# A missing tool leaves its files out (the tests then skip), except under CI=true, where it is
# an error: tools/install-deps.sh installs both.
cmake_minimum_required(VERSION 3.25)
foreach(_var REAL OUT)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "pack_compressed.cmake: -D${_var}=... is required")
  endif()
endforeach()

set(_models NegativeScaleTest/NegativeScaleTest.gltf TextureTransformTest/TextureTransformTest.gltf)
foreach(_tool gltfpack draco_transcoder)
  find_program(_path_${_tool} ${_tool})
  if(NOT _path_${_tool} AND "$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "pack_compressed.cmake: ${_tool} not found (CI=true: install it with tools/install-deps.sh)")
  endif()
endforeach()
set(_gltfpack "${_path_gltfpack}")
set(_draco "${_path_draco_transcoder}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    list(JOIN ARGN " " _cmd)
    message(FATAL_ERROR "pack_compressed.cmake: '${_cmd}' failed (${_rc}):\n${_out}")
  endif()
endfunction()

file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
foreach(_model ${_models})
  get_filename_component(_name "${_model}" NAME_WE)
  get_filename_component(_folder "${REAL}/${_model}" DIRECTORY)
  set(_in "${REAL}/${_model}")
  if(NOT EXISTS "${_in}")
    message(FATAL_ERROR "pack_compressed.cmake: ${_in} does not exist (expected the shared models)")
  endif()
  if(_gltfpack)
    run(${_gltfpack} -i "${_in}" -o "${OUT}/${_name}-q.glb")
    run(${_gltfpack} -i "${_in}" -o "${OUT}/${_name}-c.glb" -c)
    run(${_gltfpack} -i "${_in}" -o "${OUT}/${_name}-cc.glb" -cc)
    run(${_gltfpack} -i "${_in}" -o "${OUT}/${_name}-noq.glb" -noq)
    run(${_gltfpack} -i "${_in}" -o "${OUT}/${_name}-c-noq.glb" -c -noq)
    run(${_gltfpack} -i "${_in}" -o "${OUT}/${_name}-cc-noq.glb" -cc -noq)
    file(COPY "${_folder}/" DESTINATION "${OUT}/${_name}-text")
    run(${_gltfpack} -i "${OUT}/${_name}-text/${_name}.gltf" -o "${OUT}/${_name}-text/${_name}-cc.gltf" -cc)
  endif()
  if(_draco)
    run(${_draco} -i "${_in}" -o "${OUT}/${_name}-draco.glb")
  endif()
endforeach()
