// Reverse Cuthill–McKee: an order of a sparse symmetric matrix's equations that keeps its
// entries near the diagonal (a narrow envelope). The node-block factorisation orders its block
// rows by it: a frame whose members form chains, rings or a few bays then factorises in an
// envelope a block or two wide (block_profile_ldlt.hpp).
#pragma once

#include "solver/block_assembler.hpp"

#include <vector>

namespace plastica {

// The equation at each new position. The pattern of K is taken as symmetric (both triangles
// are read). Each connected part starts from a pseudo-peripheral equation (George and Liu).
std::vector<int> reverse_cuthill_mckee(const SparseMatrix& K);

} // namespace plastica
