// Test support: a free-field column's GLL element of degree p (numerics/gll_basis) and the node
// heights of nel equal elements of [0, H] (test_free_field_column, test_column_pore_pressure).
#pragma once
#include <vector>

#include "slipwave/numerics/gll_basis.hpp"
#include "slipwave/physics/column_element.hpp"

inline slipwave::physics::ColumnElement gllElement(int p) {
  slipwave::physics::ColumnElement el;
  el.degree = p;
  el.x.resize(p + 1), el.w.resize(p + 1), el.D.resize((p + 1) * (p + 1));
  slipwave::numerics::gllPointsWeights(p, el.x.data(), el.w.data());
  slipwave::numerics::lagrangeDerivativeMatrix(p, el.x.data(), el.D.data());
  return el;
}

inline std::vector<double> gllHeights(double H, int nel, const slipwave::physics::ColumnElement &el) {
  std::vector<double> z{0.0};
  for (int e = 0; e < nel; ++e)
    for (int a = 1; a <= el.degree; ++a) z.push_back(a == el.degree ? H * (e + 1) / nel : H * (e + (1 + el.x[a]) / 2) / nel);
  return z;
}
