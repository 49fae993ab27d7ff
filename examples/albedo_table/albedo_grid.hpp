// albedo_grid.hpp - the cells of the table: 32 values of mu = cos(theta)
// of the view (rows) by 32 values of the GGX alpha (columns), both at the
// centres of 32 equal steps of (0, 1].  Each cell's view and roughness are
// the floats the device sees; the quadrature reads the same floats.
#pragma once

#include <vector>

namespace albedo {

constexpr int table_size = 32;  // rows (mu) and columns (alpha)
constexpr int cell_count = table_size * table_size;

struct Cell {
    float view_x, view_z;  // the view (sqrt(1 - mu^2), 0, mu)
    float alpha;
};

// Cell (row, column) at index row * table_size + column.
std::vector<Cell> table_cells();

} // namespace albedo
