#pragma once
// The bar chart of the report's benchmark section, drawn by gnuplot as
// DIR/figures/bench_time.png: one panel per problem and element at the finest mesh measured for
// it, the time of each algorithm (bars) grouped by contact discretization, its ratio printed
// above each bar, and two horizontal lines: the model's reference time (one assembly +
// factorization + solve, ratio 1) and the target's limit (max_ratio x the reference).

#include <filesystem>

#include "reports/bench/bench_section.hpp"
#include "reports/figures/figures.hpp"

namespace cs::reports {

/// Draws the chart into `out_root`/figures/. Never throws for a plotting failure: the figure
/// carries its error, or the set says why none could be drawn (no gnuplot). Empty when `bench`
/// has no Contact benchmark with a time.
FigureSet render_bench_figures(const BenchResults& bench, const std::filesystem::path& out_root,
                               const BenchTarget& target = {}, const FigureOptions& options = {});

}  // namespace cs::reports
