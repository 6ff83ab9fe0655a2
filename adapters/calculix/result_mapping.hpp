#pragma once
// Maps a parsed .frd onto our model: CalculiX node id n is our node n - 1 (input_deck.hpp),
// and node-to-surface contact results at expanded nodes go through the .12d map first.
//
// Checks that make a wrong mapping loud rather than silent: every node of the .frd node block
// must be one of ours at our coordinates (to the 6 digits of the file), every result node id
// must map to one of our nodes, and the STRESS, DISP and FORC blocks must be present. A failed
// check throws CalculixOutputError.

#include "adapters/calculix/expansion_map.hpp"
#include "adapters/calculix/frd_reader.hpp"
#include "adapters/calculix/runner.hpp"

namespace cs::adapters::calculix {

/// Fills nodal_stress, displacement, reaction and contact of `result` from `frd`.
void map_results(const FrdFile& frd, const ExpansionMap& expansion, const solver::Model& model,
                 const solver::ContactPair& pair, CalculixResult& result);

}  // namespace cs::adapters::calculix
