#include "core/materials/stress_strain_csv.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_stress_strain_csv(text, "curve.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StressStrainCsv, reads_headers_with_units_and_converts_to_si) {
  const auto curve = parse_stress_strain_csv(
      "# uniaxial tension, specimen 3\n"
      "time_s,strain [%],stress [kPa]\n"
      "0,0,0\n1,10,2.5\n\n2,20,7.5\n3,30,16\r\n",
      "curve.csv");
  ASSERT_EQ(curve.strain.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.strain[1], 0.1);
  EXPECT_DOUBLE_EQ(curve.stress[3], 16000.0);
}

TEST(StressStrainCsv, reads_headerless_files_as_strain_and_pascal) {
  const auto curve = parse_stress_strain_csv("0;0\n0.1;100\n0.2;250\n0.3;500\n", "curve.csv");
  EXPECT_DOUBLE_EQ(curve.strain[2], 0.2);
  EXPECT_DOUBLE_EQ(curve.stress[2], 250.0);
}

TEST(StressStrainCsv, stretch_and_megapascal_columns) {
  const auto curve =
      parse_stress_strain_csv("stress_mpa\tstretch\n0\t1\n0.1\t1.1\n0.3\t1.2\n0.7\t1.3\n", "c.tsv");
  EXPECT_NEAR(curve.strain[3], 0.3, 1e-15);
  EXPECT_DOUBLE_EQ(curve.stress[3], 7.0e5);
}

TEST(StressStrainCsv, errors_name_file_line_and_column) {
  EXPECT_EQ(error_of("strain,stress\n0,0\n0.1,abc\n0.2,3\n0.3,4\n"),
            "curve.csv: line 3, column 2: \"abc\" is not a finite number");
  EXPECT_EQ(error_of("strain,stress\n0,0\n0.1\n"),
            "curve.csv: line 3: expected at least 2 fields, found 1");
  EXPECT_EQ(
      error_of("time,force\n0,0\n"),
      "curve.csv: line 1: the header names no strain column (expected e.g. \"strain,stress_kpa\")");
  EXPECT_EQ(error_of("strain,stress\n0,0\n0.1,nan\n"),
            "curve.csv: line 3, column 2: \"nan\" is not a finite number");
  EXPECT_EQ(error_of("0,0\n0.1,1\n"),
            "curve.csv: a stress-strain curve needs at least 4 samples, found 2");
}

TEST(StressStrainCsv, missing_file_is_an_input_error_naming_it) {
  const auto path = testing::scratch_dir() / "absent.csv";
  try {
    read_stress_strain_csv(path);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location().file, path.string());
  }
}

TEST(StressStrainCsv, reads_a_file) {
  const auto path = testing::scratch_dir() / "curve.csv";
  std::ofstream(path) << "strain,stress_kpa\n0,0\n0.1,4.5\n0.2,10.4\n0.3,19.4\n";
  const auto curve = read_stress_strain_csv(path);
  EXPECT_EQ(curve.stress.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.stress[3], 19400.0);
}

}  // namespace
}  // namespace viscera::core
