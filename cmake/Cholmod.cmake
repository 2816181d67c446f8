# Defines the target Constrained_fairing::Cholmod when SuiteSparse's CHOLMOD is found.
# Linking it defines CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD, so that programs can offer
# Eigen::CholmodSupernodalLLT as the sparse_linear_solver.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY)
  message(STATUS "CHOLMOD: ${CHOLMOD_LIBRARY}")
  add_library(Constrained_fairing::Cholmod INTERFACE IMPORTED)
  set_target_properties(Constrained_fairing::Cholmod PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY}"
    INTERFACE_COMPILE_DEFINITIONS CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD)
else()
  message(STATUS "CHOLMOD not found: programs use Eigen's SimplicialLDLT only")
endif()
