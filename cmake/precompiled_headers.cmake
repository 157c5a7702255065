# Precompiled headers: the heavy headers (Eigen, nlohmann-json, Catch2, the usual standard
# library ones) that nearly every source of a target parses are compiled once per target.
# On this project's 2-core CI machine that is about a third of the test build's time.
# PRIVATE: nothing of it reaches a project that uses the installed package.
# -DCCDLAB_PCH=OFF turns it off (e.g. to check that every file includes what it uses).
option(CCDLAB_PCH "Precompile the heavy headers of each target" ON)

# ccdlab_precompile_headers(TARGET [JSON] [CATCH]): Eigen and the standard headers, plus
# nlohmann-json and Catch2 when asked.
function(ccdlab_precompile_headers target)
  if(NOT CCDLAB_PCH)
    return()
  endif()
  cmake_parse_arguments(PCH "JSON;CATCH" "" "" ${ARGN})
  set(headers <Eigen/Core> <Eigen/Geometry> <algorithm> <cmath> <string> <vector>)
  if(PCH_JSON)
    list(APPEND headers <nlohmann/json.hpp>)
  endif()
  if(PCH_CATCH)
    list(PREPEND headers <catch2/catch.hpp>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
