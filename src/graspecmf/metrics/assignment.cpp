#include "graspecmf/metrics/assignment.hpp"

#include <limits>

#include "graspecmf/core/error.hpp"

namespace graspecmf::metrics {

std::vector<int> min_cost_assignment(const Eigen::MatrixXd& cost) {
  if (cost.rows() != cost.cols()) throw Error("assignment: the cost matrix must be square");
  if (!cost.allFinite()) throw Error("assignment: the cost matrix has a non-finite entry");
  const int n = static_cast<int>(cost.rows());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // 1-based arrays; row_of[j] = the row matched to column j (0 = none), with a virtual column 0
  // that holds the row being inserted. u, v are the dual potentials.
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
  std::vector<int> row_of(n + 1, 0), previous(n + 1, 0);
  std::vector<double> reduced(n + 1);
  std::vector<char> used(n + 1);
  for (int i = 1; i <= n; ++i) {
    row_of[0] = i;
    int j0 = 0;
    std::fill(reduced.begin(), reduced.end(), kInf);
    std::fill(used.begin(), used.end(), 0);
    // Grow a shortest-path tree from row i until it reaches a free column.
    do {
      used[j0] = 1;
      const int i0 = row_of[j0];
      double delta = kInf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double c = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (c < reduced[j]) {
          reduced[j] = c;
          previous[j] = j0;
        }
        if (reduced[j] < delta) {
          delta = reduced[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) {
          u[row_of[j]] += delta;
          v[j] -= delta;
        } else {
          reduced[j] -= delta;
        }
      }
      j0 = j1;
    } while (row_of[j0] != 0);
    // Augment along the path back to the virtual column.
    do {
      const int j1 = previous[j0];
      row_of[j0] = row_of[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> column(static_cast<std::size_t>(n));
  for (int j = 1; j <= n; ++j) column[static_cast<std::size_t>(row_of[j] - 1)] = j - 1;
  return column;
}

}  // namespace graspecmf::metrics
