#pragma once
// GetFEM hexahedral mesh of a StructuredBody (internal to fe_contact).
//
// References: see fe_body.hpp.
// Known deviations: see fe_body.hpp (trilinear mapped cells).

#include <Eigen/Dense>
#include <getfem/getfem_mesh.h>
#include <getfem/getfem_models.h>

#include <cstddef>
#include <limits>
#include <vector>

#include "ferro/fe_contact/fe_body.hpp"

namespace ferro::fe_contact::detail {

constexpr std::size_t kNoCell = std::numeric_limits<std::size_t>::max();

/// Adds the active cells of `body` to `m` as trilinear hexahedra (vertex order: s fastest, then
/// t, w; local vertex c has offsets (c & 1, (c >> 1) & 1, c >> 2)) and returns the convex index
/// of cell (i, j, k) at (k * nt + j) * ns + i (kNoCell for an inactive cell).
std::vector<std::size_t> build_structured_mesh(const StructuredBody& body, getfem::mesh& m);

/// Local face of a hexahedron of build_structured_mesh whose vertices all have c >> 2 == top
/// (1: the face at the cell's upper w line, 0: the lower).
bgeot::short_type hexahedron_w_face(const getfem::mesh& m, std::size_t convex, int top);

/// Solves K X = B for the symmetric positive definite stiffness `K` restricted to the free DOFs
/// (free_index[i] >= 0 is the row of DOF i; clamped DOFs have -1), CHOLMOD supernodal Cholesky.
/// B and X have one row per free DOF. Throws std::runtime_error when the factorisation fails.
Eigen::MatrixXd solve_clamped(const getfem::model_real_sparse_matrix& K,
                              const std::vector<long>& free_index, long nfree,
                              const Eigen::MatrixXd& B, const char* where);

}  // namespace ferro::fe_contact::detail
