#pragma once
// Exact minimum-cost perfect assignment on a dense square cost matrix (the Hungarian method with
// potentials and shortest augmenting paths, O(n³)).

#include <Eigen/Core>
#include <vector>

namespace graspecmf::metrics {

// column[i] = the column assigned to row i, minimising Σ cost(i, column[i]). Throws Error if the
// matrix is not square or holds a non-finite entry. An empty matrix gives an empty assignment.
std::vector<int> min_cost_assignment(const Eigen::MatrixXd& cost);

}  // namespace graspecmf::metrics
