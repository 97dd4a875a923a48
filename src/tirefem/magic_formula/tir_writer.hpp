#pragma once
// Writer of PAC2002 `.tir` property files: [MDI_HEADER], [UNITS] (SI), [MODEL] (PROPERTY_FILE_FORMAT =
// 'PAC2002', FITTYP = 6 as MFeval's reader expects for MF 5.2), [DIMENSION], [VERTICAL], the four range
// sections, [SCALING_COEFFICIENTS], [LONGITUDINAL_COEFFICIENTS], [OVERTURNING_COEFFICIENTS],
// [LATERAL_COEFFICIENTS], [ROLLING_COEFFICIENTS], [ALIGNING_COEFFICIENTS]. Each coefficient has a `$`
// comment with its description and, when `TirFile::notes` has one for the key, the note. Numbers are
// written in the shortest form that reads back to the identical double, so write -> read is exact.
// Keys the reader kept in `TirFile::other_entries` are written back into their section.
#include <filesystem>
#include <string>

#include "tirefem/magic_formula/coefficients.hpp"

namespace tirefem {

std::string format_tir(const TirFile& file);
// Throws std::runtime_error naming the file when it cannot be written.
void write_tir_file(const std::filesystem::path& path, const TirFile& file);

}  // namespace tirefem
