# The part of the core that reads, preprocesses and validates shader text:
# what `check` runs and what the fuzz targets (tests/fuzz) build with clang.
# One list, so that a new dependency of core/source is added in one place.
# program.cpp comes along because the host-input table sets uniforms on a
# Program; the fuzz targets never call it, but it links against libepoxy.
# supersampling.cpp comes with the table: it moves gl_FragCoord by a sample's
# offset; and inputs.cpp: the table records iDate as `render --date` reads it.
# tweak.cpp lifts a scene's numbers out of its text for the twin; one_line.cpp
# cuts what an error quotes from the text to a length a line can hold;
# address_space.cpp: a Program asks it for room before the driver builds.
# glslang itself runs in the worker, a program of its own
# (RM_GLSLANG_WORKER_SOURCES): both lists build with the glslang_worker/
# protocol.
set(RM_SHADER_TEXT_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/source.cpp
  ${CMAKE_CURRENT_LIST_DIR}/glslviewer_passes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/files.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lexing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/dialect_names.cpp
  ${CMAKE_CURRENT_LIST_DIR}/diagnostics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/left_open.cpp
  ${CMAKE_CURRENT_LIST_DIR}/glslang_words.cpp
  ${CMAKE_CURRENT_LIST_DIR}/glslang_client.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../glslang_worker/protocol.cpp
  ${CMAKE_CURRENT_LIST_DIR}/channel_spec.cpp
  ${CMAKE_CURRENT_LIST_DIR}/host_inputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/supersampling.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/program.cpp
  ${CMAKE_CURRENT_LIST_DIR}/user_uniforms.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tweak.cpp
  ${CMAKE_CURRENT_LIST_DIR}/one_line.cpp
  ${CMAKE_CURRENT_LIST_DIR}/address_space.cpp
)
set(RM_GLSLANG_WORKER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/../glslang_worker/main.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../glslang_worker/glslang_work.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../glslang_worker/tree_checks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../glslang_worker/sandbox.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../glslang_worker/protocol.cpp
  ${CMAKE_CURRENT_LIST_DIR}/deep_stack.cpp
  ${CMAKE_CURRENT_LIST_DIR}/address_space.cpp
)
# Where the host finds the worker: <prefix>/libexec/raymarching installed,
# else where this build put it. Whatever builds glslang_client.cpp takes
# RM_GLSLANG_WORKER_PATHS as its compile definitions.
set(RM_GLSLANG_WORKER_INSTALL_DIR "libexec/raymarching")
set(RM_GLSLANG_WORKER_PATHS
  RM_GLSLANG_WORKER_INSTALLED="${RM_GLSLANG_WORKER_INSTALL_DIR}/raymarching-glslang"
  RM_GLSLANG_WORKER_BUILT="$<TARGET_FILE:raymarching-glslang>")
