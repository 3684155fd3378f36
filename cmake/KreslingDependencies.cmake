# System dependencies, found from Debian's -dev packages. A missing one stops the build
# with the package to install, rather than a cryptic compiler error later.

function(kresling_missing what package)
  message(FATAL_ERROR
    "kresling: ${what} was not found.\n"
    "Install it with:  apt-get install ${package}\n"
    "(or run `make test`, which installs the Debian packages it needs when run as root).")
endfunction()

# Eigen 3 (header only).
find_package(Eigen3 3.3 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  kresling_missing("Eigen 3" "libeigen3-dev")
endif()

# SuiteSparse: CHOLMOD (positive-definite tangents) and UMFPACK (indefinite ones).
# Debian's SuiteSparse 5.x ships no CMake config, so look for headers and libraries.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h
  PATH_SUFFIXES suitesparse
  HINTS ENV SUITESPARSE_ROOT)
foreach(lib cholmod umfpack amd colamd camd ccolamd suitesparseconfig)
  string(TOUPPER ${lib} LIB)
  find_library(SUITESPARSE_${LIB}_LIBRARY ${lib} HINTS ENV SUITESPARSE_ROOT)
  if(NOT SUITESPARSE_${LIB}_LIBRARY)
    kresling_missing("SuiteSparse library '${lib}'" "libsuitesparse-dev")
  endif()
  list(APPEND SUITESPARSE_LIBRARIES ${SUITESPARSE_${LIB}_LIBRARY})
endforeach()
if(NOT SUITESPARSE_INCLUDE_DIR)
  kresling_missing("SuiteSparse headers (cholmod.h)" "libsuitesparse-dev")
endif()
add_library(kresling_suitesparse INTERFACE)
target_include_directories(kresling_suitesparse SYSTEM INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(kresling_suitesparse INTERFACE ${SUITESPARSE_LIBRARIES})

# LAPACK: the N5B8 centre of a quad is a 3 x 2 least-squares solve, done with LAPACK's
# dgelsd as GNU Octave does, so that models agree with MERLIN2's to the last bit.
find_package(LAPACK QUIET)
if(NOT LAPACK_FOUND)
  kresling_missing("LAPACK" "liblapack-dev")
endif()

find_package(Threads REQUIRED)

if(KRESLING_BUILD_TESTS)
  find_package(GTest QUIET)
  if(NOT GTest_FOUND)
    kresling_missing("GoogleTest" "libgtest-dev")
  endif()
endif()
