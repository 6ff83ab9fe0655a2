#pragma once
// The commit of an output transaction (platform/output_transaction.hpp) and its roll-forward.
//
// A staged set becomes the directory's set in three steps:
//   1. its entry names are written into the staging directory as `.contact-suite.set`;
//   2. the staging directory is renamed to DIR/.contact-suite.commit: one atomic step after
//      which the new set is decided (the journal);
//   3. roll_forward: every entry of the journal is renamed into DIR, results.json last; a file
//      replaces its predecessor atomically (rename(2)); a directory, or an entry whose type
//      changes, first moves its predecessor into DIR/.contact-suite.old. Entries the previous
//      set listed in DIR/.contact-suite.set and the new one lacks move there too. The list is
//      installed, and the journal and DIR/.contact-suite.old are removed.
// Every step of 3 can be repeated after a kill (an entry already moved is skipped), so
// recover_output_directory, run under the lock by the next transaction, completes it.
// Only names listed in a set are ever moved: entries the tool did not write are not touched.

#include <filesystem>

namespace cs::platform {

/// Steps 1-3 for `staging`, a directory inside `dir`. Throws OutputError naming the
/// cause when a write or rename fails (before step 2, `dir` is unchanged).
void commit_staged_set(const std::filesystem::path& dir, const std::filesystem::path& staging);

/// Finishes an interrupted commit in `dir` (step 3 from its journal) and removes what killed
/// transactions left: `.contact-suite.old` and `.contact-suite.staging-*`. The caller holds the
/// lock of `dir`. Throws OutputError when a rename fails.
void recover_output_directory(const std::filesystem::path& dir);

}  // namespace cs::platform
