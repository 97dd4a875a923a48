#pragma once
// The coefficients of a PAC2002 / MF-Tyre 5.2 Magic Formula tyre, as a `.tir` property file holds them
// (SI units, TYDEX/ISO W-axis system). Member names are the `.tir` keys, spelt as Chrono's ChPac02Tire and
// MFeval read them, so that the equations in evaluator.cpp read like the book's.
//
// A coefficient missing from a file takes its neutral value: 0 for most, 1 for the L* scaling factors, the
// values of `coefficient_table()` otherwise. PAC2002 has PKY1-PKY3 only (the sine's factor is the constant 2:
// PKY4..PKY7 belong to MF 6.1) and RBX1-RBX2, RBY1-RBY3 (RBX3 is MF 6.1's camber term, kept here with neutral
// value 0 so that a file that has it reads back unchanged).
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tirefem {

struct MagicFormulaCoefficients {
  // [MDI_HEADER] / [MODEL]
  double FILE_VERSION = 3.0;
  double FITTYP = 6;  // 6 (or 21): MF 5.2 / PAC2002 in MFeval's reader; 61, 62: MF 6.1, 6.2
  double USE_MODE = 4;
  double VXLOW = 1;
  double LONGVL = 16.7;
  // [DIMENSION]
  double UNLOADED_RADIUS = 0, WIDTH = 0, ASPECT_RATIO = 0, RIM_RADIUS = 0, RIM_WIDTH = 0;
  // [VERTICAL]
  double FNOMIN = 0, VERTICAL_STIFFNESS = 0, VERTICAL_DAMPING = 0, BREFF = 0, DREFF = 0, FREFF = 0;
  double Q_RE0 = 1, Q_V1 = 0, Q_V2 = 0, Q_FZ1 = 0, Q_FZ2 = 0, Q_FCX = 0, Q_FCY = 0;
  // ranges
  double KPUMIN = -1.5, KPUMAX = 1.5, ALPMIN = -1.5708, ALPMAX = 1.5708, CAMMIN = -0.26181, CAMMAX = 0.26181;
  double FZMIN = 0, FZMAX = 0;
  // [SCALING_COEFFICIENTS]
  double LFZO = 1, LCX = 1, LMUX = 1, LEX = 1, LKX = 1, LHX = 1, LVX = 1, LGAX = 1;
  double LCY = 1, LMUY = 1, LEY = 1, LKY = 1, LHY = 1, LVY = 1, LGAY = 1;
  double LTR = 1, LRES = 1, LGAZ = 1, LXAL = 1, LYKA = 1, LVYKA = 1, LS = 1;
  double LSGKP = 1, LSGAL = 1, LGYR = 1, LMX = 1, LVMX = 1, LMY = 1;
  // [LONGITUDINAL_COEFFICIENTS]
  double PCX1 = 0, PDX1 = 0, PDX2 = 0, PDX3 = 0, PEX1 = 0, PEX2 = 0, PEX3 = 0, PEX4 = 0;
  double PKX1 = 0, PKX2 = 0, PKX3 = 0, PHX1 = 0, PHX2 = 0, PVX1 = 0, PVX2 = 0;
  double RBX1 = 0, RBX2 = 0, RBX3 = 0, RCX1 = 0, REX1 = 0, REX2 = 0, RHX1 = 0;
  double PTX1 = 0, PTX2 = 0, PTX3 = 0;
  // [OVERTURNING_COEFFICIENTS]
  double QSX1 = 0, QSX2 = 0, QSX3 = 0;
  // [LATERAL_COEFFICIENTS]
  double PCY1 = 0, PDY1 = 0, PDY2 = 0, PDY3 = 0, PEY1 = 0, PEY2 = 0, PEY3 = 0, PEY4 = 0;
  double PKY1 = 0, PKY2 = 0, PKY3 = 0, PHY1 = 0, PHY2 = 0, PHY3 = 0;
  double PVY1 = 0, PVY2 = 0, PVY3 = 0, PVY4 = 0;
  double RBY1 = 0, RBY2 = 0, RBY3 = 0, RCY1 = 0, REY1 = 0, REY2 = 0, RHY1 = 0, RHY2 = 0;
  double RVY1 = 0, RVY2 = 0, RVY3 = 0, RVY4 = 0, RVY5 = 0, RVY6 = 0;
  double PTY1 = 0, PTY2 = 0;
  // [ROLLING_COEFFICIENTS]
  double QSY1 = 0, QSY2 = 0, QSY3 = 0, QSY4 = 0;
  // [ALIGNING_COEFFICIENTS]
  double QBZ1 = 0, QBZ2 = 0, QBZ3 = 0, QBZ4 = 0, QBZ5 = 0, QBZ9 = 0, QBZ10 = 0, QCZ1 = 0;
  double QDZ1 = 0, QDZ2 = 0, QDZ3 = 0, QDZ4 = 0, QDZ6 = 0, QDZ7 = 0, QDZ8 = 0, QDZ9 = 0;
  double QEZ1 = 0, QEZ2 = 0, QEZ3 = 0, QEZ4 = 0, QEZ5 = 0, QHZ1 = 0, QHZ2 = 0, QHZ3 = 0, QHZ4 = 0;
  double SSZ1 = 0, SSZ2 = 0, SSZ3 = 0, SSZ4 = 0, QTZ1 = 0, MBELT = 0;
};

// One numeric `.tir` key: where it is written, which member holds it, its neutral value and a short
// description for the writer's `$` comment. `optional` keys are written only when they differ from the
// neutral value (they are not part of every PAC2002 file).
struct CoefficientInfo {
  std::string_view key;
  std::string_view section;  // without brackets, e.g. "LONGITUDINAL_COEFFICIENTS"
  double MagicFormulaCoefficients::*member;
  double neutral;
  std::string_view description;
  bool optional = false;
};

// Every numeric key, in the order the writer writes them.
std::span<const CoefficientInfo> coefficient_table();
// nullptr when `key` (upper case) is not a numeric coefficient.
const CoefficientInfo* find_coefficient(std::string_view key);

// A key the reader does not know, kept verbatim (value text as in the file) so that the writer can write
// it back into its section.
struct TirEntry {
  std::string section;
  std::string key;
  std::string value;
};

// A whole property file: the numeric coefficients, the text fields, other keys, and per-coefficient notes
// that the writer appends to the coefficient's `$` comment (e.g. "not determined by the rig: neutral value").
struct TirFile {
  MagicFormulaCoefficients coefficients;
  std::string file_type = "tir";
  std::string file_format = "ASCII";
  std::string property_file_format = "PAC2002";
  std::string tyre_side = "LEFT";
  std::vector<std::string> header_comments;  // written as "! : COMMENT : ..." lines in [MDI_HEADER]
  std::vector<TirEntry> other_entries;
  std::map<std::string, std::string> notes;  // key -> note
};

}  // namespace tirefem
