// .tir reader and writer: two public files, write -> read round trip, malformed files.
#include <gtest/gtest.h>

#include <string>

#include "tirefem/magic_formula/tir_reader.hpp"
#include "tirefem/magic_formula/tir_writer.hpp"

namespace tirefem {
namespace {

std::string data_file(const char* name) {
  return std::string(TIREFEM_SOURCE_DIR) + "/tests/verification/data/magic_formula/" + name;
}

std::string error_of(std::string_view text) {
  try {
    parse_tir(text, "bad.tir");
  } catch (const TirFileError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MagicFormulaTir, ReadsTwoPublicFiles) {
  const TirFile vw = read_tir_file(data_file("mf_185_80R14.tir"));
  EXPECT_EQ(vw.property_file_format, "PAC2002");
  EXPECT_EQ(vw.tyre_side, "LEFT");
  EXPECT_EQ(vw.coefficients.FILE_VERSION, 3.0);
  EXPECT_EQ(vw.coefficients.FNOMIN, 3800);
  EXPECT_EQ(vw.coefficients.LONGVL, 16.7);
  EXPECT_EQ(vw.coefficients.UNLOADED_RADIUS, 0.376);
  EXPECT_EQ(vw.coefficients.VERTICAL_STIFFNESS, 1.75e5);
  EXPECT_EQ(vw.coefficients.PKY1, -12.536);
  EXPECT_EQ(vw.coefficients.PDX3, 9.9376e-6);
  EXPECT_EQ(vw.coefficients.SSZ4, -0.16022);
  EXPECT_EQ(vw.header_comments.size(), 10u);

  const TirFile sedan = read_tir_file(data_file("Sedan_Pac02Tire.tir"));
  EXPECT_EQ(sedan.coefficients.FNOMIN, 4850);
  EXPECT_EQ(sedan.coefficients.LFZO, 0.81);
  EXPECT_EQ(sedan.coefficients.PKY1, -21.92);
  EXPECT_EQ(sedan.coefficients.RBX1, 0.0);   // missing: neutral
  EXPECT_EQ(sedan.coefficients.LVYKA, 1.0);  // present, 1
  EXPECT_EQ(sedan.coefficients.FITTYP, 6.0); // missing: PAC2002 default
  ASSERT_EQ(sedan.other_entries.size(), 1u);  // MESSAGES = 'YES' is kept
  EXPECT_EQ(sedan.other_entries[0].key, "MESSAGES");
  EXPECT_EQ(sedan.other_entries[0].section, "MODEL");
}

TEST(MagicFormulaTir, WriteReadRoundTripIsExact) {
  TirFile file = read_tir_file(data_file("mf_185_80R14.tir"));
  file.coefficients.PKX1 = 0.1 + 0.2;  // not representable in few digits
  file.coefficients.Q_FZ1 = 1.0 / 3.0;
  file.notes["PDX3"] = "not determined by the rig: neutral value";
  const std::string text = format_tir(file);
  EXPECT_NE(text.find("$Variation of friction Mux with camber squared (not determined by the rig: neutral value)"),
            std::string::npos);
  EXPECT_NE(text.find("FITTYP                   = 6"), std::string::npos);
  const TirFile again = parse_tir(text, "written.tir");
  for (const CoefficientInfo& info : coefficient_table())
    EXPECT_EQ(again.coefficients.*(info.member), file.coefficients.*(info.member)) << info.key;
  EXPECT_EQ(again.tyre_side, file.tyre_side);
  EXPECT_EQ(again.header_comments, file.header_comments);
  // A second round trip writes the same text (notes live in TirFile, not in the numbers: carried over).
  TirFile again_with_notes = again;
  again_with_notes.notes = file.notes;
  EXPECT_EQ(format_tir(again_with_notes), text);
}

TEST(MagicFormulaTir, MalformedFilesGiveOneLineErrorsNamingLineAndKey) {
  const std::string number = error_of("[LONGITUDINAL_COEFFICIENTS]\nPCX1 = 1.5\nPKX1 = 1.2.3 $slip stiffness\n");
  EXPECT_EQ(number, "bad.tir:3: PKX1: expected a number, got '1.2.3'");
  const std::string string_value = error_of("[VERTICAL]\nFNOMIN = 'heavy'\n");
  EXPECT_EQ(string_value, "bad.tir:2: FNOMIN: expected a number, got the string 'heavy'");
  const std::string empty = error_of("[MODEL]\n\nLONGVL =  $speed\n");
  EXPECT_EQ(empty, "bad.tir:3: LONGVL: expected a number, got nothing");
  const std::string units = error_of("[UNITS]\nLENGTH = 'mm'\n");
  EXPECT_EQ(units, "bad.tir:2: LENGTH: unit 'mm' is not supported (SI units only: meter, newton, radian, kg, second)");
  const std::string garbage = error_of("[MODEL]\nthis is not a key\n");
  EXPECT_EQ(garbage, "bad.tir:2: this is not a key: expected 'KEY = value'");
  // An MF 6.1 file shares most keys but not the formulas: refused rather than evaluated as PAC2002.
  const std::string version = error_of("[MODEL]\nPROPERTY_FILE_FORMAT = 'PAC2002'\nFITTYP = 61 $Magic Formula version number\n");
  EXPECT_EQ(version, "bad.tir:3: FITTYP: 61 is not MF 5.2 / PAC2002 (FITTYP 6 or 21), the only version read here (it is MF 6.1)");
  EXPECT_EQ(parse_tir("[MODEL]\nFITTYP = 21\n", "mf52.tir").coefficients.FITTYP, 21);
  for (const std::string& e : {number, string_value, empty, units, garbage, version}) EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(MagicFormulaTir, UnknownKeysAreKeptAndWrittenBack) {
  const TirFile file = parse_tir("[MODEL]\nLONGVL = 20\nSOMETHING_NEW = 42 $x\n[MY_SECTION]\nA = 'b'\n", "new.tir");
  EXPECT_EQ(file.coefficients.LONGVL, 20);
  EXPECT_EQ(file.coefficients.LMUX, 1.0);
  ASSERT_EQ(file.other_entries.size(), 2u);
  const TirFile again = parse_tir(format_tir(file), "again.tir");
  ASSERT_EQ(again.other_entries.size(), 2u);
  EXPECT_EQ(again.other_entries[0].value, "42");
  EXPECT_EQ(again.other_entries[1].section, "MY_SECTION");
}

}  // namespace
}  // namespace tirefem
