// The reference element of a 1D free-field column on [-1, 1] (physics/free_field_column.hpp,
// physics/column_pore_pressure.hpp): its degree, GLL points x and weights w (p+1 each) and
// derivative matrix D[i*(p+1) + j] = l_j'(x_i) (the caller takes them from numerics/gll_basis).
// Left empty: degree 1 (points -1, 1, weights 1, D rows (-1/2, 1/2)).
#pragma once
#include <vector>

namespace slipwave::physics {

constexpr int kMaxColumnDegree = 8;
struct ColumnElement {
  int                 degree = 1;
  std::vector<double> x, w, D;
};

// The element with its degree-1 tables filled in when left empty.
ColumnElement completeColumnElement(const ColumnElement &element);

} // namespace slipwave::physics
