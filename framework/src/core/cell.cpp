#include "antipode/interfaces/cell.hpp"

#include "antipode/core/error.hpp"

namespace antipode {

void Cell::restore(const CellState& /*state*/) {
  throw Error("this cell cannot restore a saved world (its save() gives none)");
}

}  // namespace antipode
