// Each submission's own cases: a graded lab's seed comes from the instructor's secret and
// the bytes of the submission's files for that lab, so that every submission, and every
// resubmission with a changed file, draws cases of its own. A student who special-cases
// an input the feedback showed meets new cases on the next submission; the same files
// and the same secret draw the same cases, so the instructor can reproduce any grade.
// The seed is never shown: the judge's process reads it from LABKIT_SEED_FILE.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace runner {

// SHA-256 (FIPS 180-4) of `bytes`.
std::array<std::uint8_t, 32> sha256(std::string_view bytes);

// The seed of lab `lab_id` for a submission whose files for it are `files` (manifest
// path -> contents): the first 63 bits of SHA-256 over the secret, the lab and each
// file's path, length and bytes (every part length-prefixed, so no two inputs run
// together), as decimal text the harness reads as that number.
std::string submission_seed(const std::string& secret, const std::string& lab_id,
                            const std::map<std::string, std::string>& files);

}  // namespace runner
