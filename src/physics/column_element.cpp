#include "slipwave/physics/column_element.hpp"

namespace slipwave::physics {

ColumnElement completeColumnElement(const ColumnElement &element) {
  ColumnElement full = element;
  if (full.degree == 1 && full.x.empty()) full.x = {-1, 1}, full.w = {1, 1}, full.D = {-0.5, 0.5, -0.5, 0.5};
  return full;
}

} // namespace slipwave::physics
