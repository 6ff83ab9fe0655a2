#pragma once
// Reads CalculiX's record of how it expanded the 2D elements into 3D ones (job.12d) and maps
// the expanded nodes back to the nodes of the deck.
//
// ccx solves plane-strain and axisymmetric elements as one layer of 3D elements (CPE4/CAX4 ->
// C3D8, CPE8/CAX8 -> C3D20). Most results are written at the deck's nodes, but node-to-surface
// contact results (CONTACT block of the .frd) are written at the expanded slave nodes. The
// .12d file lists, per element:
//     ELEMENT <id> with label "CPE4    " and with nodes:
//     <n1> ... <n4|n8>
//     is expanded into a "C3D8  E " element with topology:
//     <m1> ... <m8|m20>
// The expanded topology puts the copies of 2D node j (0-based) at
//   4 nodes: m[j] (one face) and m[j + 4] (the other);
//   8 nodes, corner j < 4: m[j], m[j + 4] and m[16 + j] (mid-thickness);
//            mid-side 4 + k: m[8 + k] and m[12 + k].
// Malformed or truncated text throws CalculixOutputError naming the line.

#include <filesystem>
#include <string_view>
#include <unordered_map>

namespace cs::adapters::calculix {

/// Expanded node id -> deck node id.
using ExpansionMap = std::unordered_map<int, int>;

/// Parses .12d text; `source` names it in messages.
ExpansionMap parse_expansion(std::string_view text, std::string_view source = "12d");

/// Reads and parses a .12d file; a missing file gives an empty map (no 2D elements).
ExpansionMap read_expansion(const std::filesystem::path& path);

/// The deck node of an id that may be an expanded one: itself when it is not in the map.
inline int deck_node(const ExpansionMap& map, int id) {
  const auto it = map.find(id);
  return it == map.end() ? id : it->second;
}

}  // namespace cs::adapters::calculix
