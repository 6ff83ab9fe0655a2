#pragma once
// Fill-reducing orderings computed outside CHOLMOD: METIS nested dissection of the quotient
// graph of supervariables (e.g. the two DOFs of a node), expanded to equations.
//
// Ordering the node graph instead of the DOF graph gives the same separators with a quarter of
// the edges (2 DOFs per node), so METIS runs several times faster, and keeps the DOFs of a node
// together, which helps supernode formation.

#include <mutex>
#include <vector>

#include <Eigen/SparseCore>

namespace cs::solver {

/// The turn that every call into METIS holds, direct or through CHOLMOD's analysis with its
/// METIS or NESDIS orderings. METIS reseeds libc's random generator at each call and draws from
/// it while it orders. Where that generator is the whole process's, two calls at once
/// interleave their draws and return other orderings, so the same matrix was factored with
/// other round-off and the results moved with the schedule of a run's workers: the turn is a
/// lock. Where each thread draws from its own (rand_is_per_thread), it holds nothing.
std::unique_lock<std::mutex> metis_turn();

/// The number of graph vertices from which the first level of the nested dissection is taken
/// outside METIS (a vertex separator, then one METIS ordering per part), so that the two parts
/// can be ordered at once on a spare core (spare_cores.hpp). Below it, one METIS call orders all.
inline constexpr int kSplitFrom = 200'000;

/// The METIS nested-dissection ordering of the symmetric matrix whose lower triangle is
/// `A_lower`, computed on the graph whose vertices are the groups of `group_of_equation`
/// (group index per equation, 0 <= group < n_groups; equations of a group are eliminated
/// consecutively, in increasing order; an equation with a negative group is left out of the
/// graph and of the result, as if its rows and columns were deleted). Returns perm with
/// perm[k] = the equation eliminated k-th (CHOLMOD's and METIS's convention), the same from any
/// thread and whether or not a spare core was idle (from kSplitFrom groups on, the two parts of
/// the first separator are ordered by separate METIS calls). Throws std::runtime_error if METIS
/// fails.
std::vector<int> metis_quotient_ordering(const Eigen::SparseMatrix<double>& A_lower,
                                         const std::vector<int>& group_of_equation);

/// METIS's vertex separator of the same quotient graph (groups as in metis_quotient_ordering):
/// per equation 0 or 1 for the side it lies on, 2 if its vertex is in the separator, -1 if left
/// out. No entry of A couples an equation of side 0 with one of side 1. Throws
/// std::runtime_error if METIS fails.
std::vector<int> quotient_bisection(const Eigen::SparseMatrix<double>& A_lower,
                                    const std::vector<int>& group_of_equation);

}  // namespace cs::solver
