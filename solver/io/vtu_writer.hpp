#pragma once
// Writes a Mesh and fields on it as a VTK XML UnstructuredGrid file (.vtu) that ParaView opens.
//
// Points are written as (x, z, 0): the mesh's own coordinates, z on the file's second axis.
// Cells: VTK_QUAD (9) for Q4, VTK_QUADRATIC_QUAD (23) for Q8, whose VTK node order (4 corners,
// then the mid-edge nodes of edges 0-1, 1-2, 2-3, 3-0) is the Mesh's. Cell data "body" holds the
// body index of every element. Numbers are written in ASCII with the shortest representation
// that reads back to the same double (full precision).
//
// The file is written to a temporary file beside it and renamed into place, so a reader never
// sees half a file and an error leaves no file behind. Non-finite values are refused (VtuError
// naming the field): a NaN in an output file would hide a failed computation.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "solver/mesh/mesh.hpp"

namespace cs::solver {

/// One field to write: n_components values per node (point data) or per element (cell data),
/// stored node by node (element by element). A 2-component point field (a displacement (u, w))
/// is written as a 3-component vector (u, w, 0), so that ParaView can warp the mesh by it.
struct VtuField {
  std::string name;
  int n_components = 1;
  std::vector<double> values;
  bool point_data = true;
};

/// A field or mesh that cannot be written, or a file that cannot be; the message names the
/// field or the path and the cause.
class VtuError : public std::runtime_error {
 public:
  explicit VtuError(const std::string& what) : std::runtime_error(what) {}
};

/// The .vtu document for `mesh` and `fields`, with `comment` (when not empty) as an XML comment
/// after the declaration. Throws VtuError on a field of the wrong size, a repeated or empty name,
/// a non-finite value, connectivity that refers to a missing node, or a comment holding "--".
std::string vtu_document(const Mesh& mesh, const std::vector<VtuField>& fields,
                         std::string_view comment = {});

/// Writes vtu_document(mesh, fields, comment) to `path` atomically (temporary file, then
/// rename). Throws VtuError (and leaves no file) on bad input or an I/O failure.
void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields,
               std::string_view comment = {});

}  // namespace cs::solver
