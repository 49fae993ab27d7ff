// albedo_grid.cpp - the view and roughness of each cell.
#include "albedo_grid.hpp"

#include <cmath>

namespace albedo {

std::vector<Cell> table_cells()
{
    std::vector<Cell> cells;
    for (int row = 0; row < table_size; ++row) {
        for (int column = 0; column < table_size; ++column) {
            const float mu = (row + 0.5f) / table_size;
            const float alpha = (column + 0.5f) / table_size;
            cells.push_back({std::sqrt(1.0f - mu * mu), mu, alpha});
        }
    }
    return cells;
}

} // namespace albedo
