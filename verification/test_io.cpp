// Unit tests for solver/io: HDF5 run files (round trip, layout seen by h5dump, atomic failure)
// and numeric CSV (round trip, header detection, comments, error locations).
#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/hdf5_run.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

namespace fs = std::filesystem;
using kolsky::io::CsvTable;
using kolsky::io::RunRecord;
using kolsky::io::Series;

namespace {

struct TempDir : kolsky::testing::TempDir {
  TempDir() : kolsky::testing::TempDir("kolsky_test_io") {}
};


void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

RunRecord sample_run() {
  RunRecord rec;
  rec.meta = nlohmann::json::parse(R"({
    "scene": {"bars": {"incident": {"length": 4.1, "material": "steel"}}, "list": [1, 2.5, "x"]},
    "git_commit": "abc123", "build_type": "Release", "kolsky_version": "0.1.0",
    "failure": "", "complete": true, "seed": 42,
    "nested": {"a": [1, {"b": null}], "unicode": "\u03b5 strain"}
  })");
  // Names deliberately not in alphabetical order: the file must keep the declared order.
  rec.probes.push_back({"z_strain_incident", "1", {0.0, 1e-6, 2e-6}, {0.0, -1.5e-4, -3.25e-4}});
  rec.probes.push_back({"a_stress_back", "Pa", {0.0, 1e-6}, {1.0e6, 2.0e6}});
  rec.probes.push_back({"empty", "m/s", {}, {}});
  return rec;
}

}  // namespace

TEST(IoHdf5Run, RoundTripRestoresMetaAndProbesExactly) {
  TempDir dir;
  const RunRecord in = sample_run();
  const std::string path = dir.file("run.h5");
  kolsky::io::write_run_hdf5(path, in);
  const RunRecord out = kolsky::io::read_run_hdf5(path);
  EXPECT_EQ(out.meta, in.meta);
  ASSERT_EQ(out.probes.size(), in.probes.size());
  for (size_t i = 0; i < in.probes.size(); ++i) {
    EXPECT_EQ(out.probes[i].name, in.probes[i].name);
    EXPECT_EQ(out.probes[i].unit, in.probes[i].unit);
    EXPECT_EQ(out.probes[i].t, in.probes[i].t);  // doubles stored as doubles: bit-exact
    EXPECT_EQ(out.probes[i].value, in.probes[i].value);
  }
  EXPECT_EQ(dir.n_entries(), 1u) << "no temporary file may remain";
}

TEST(IoHdf5Run, LayoutIsReadableByH5dump) {
  const char* h5dump = "/usr/bin/h5dump";
  if (access(h5dump, X_OK) != 0) GTEST_SKIP() << "h5dump not installed";
  TempDir dir;
  const std::string path = dir.file("run.h5");
  kolsky::io::write_run_hdf5(path, sample_run());
  const std::string cmd = std::string(h5dump) + " -A '" + path + "' 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string dump;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) dump.append(buf, n);
  ASSERT_EQ(pclose(pipe), 0) << dump;
  for (const char* needle :
       {"GROUP \"meta\"", "ATTRIBUTE \"scene\"", "ATTRIBUTE \"git_commit\"", "\"abc123\"",
        "ATTRIBUTE \"build_type\"", "ATTRIBUTE \"kolsky_version\"", "ATTRIBUTE \"failure\"",
        "ATTRIBUTE \"complete\"", "ATTRIBUTE \"meta_json\"", "GROUP \"probes\"",
        "GROUP \"a_stress_back\"", "DATASET \"t\"", "DATASET \"value\"", "ATTRIBUTE \"unit\"",
        "\"Pa\"", "\"s\""})
    EXPECT_NE(dump.find(needle), std::string::npos) << "missing " << needle << " in\n" << dump;
}

TEST(IoHdf5Run, MetaDefaultsWhenKeysAreMissing) {
  TempDir dir;
  RunRecord rec;
  rec.meta = {{"scene", {{"x", 1}}}};
  const std::string path = dir.file("defaults.h5");
  kolsky::io::write_run_hdf5(path, rec);
  const RunRecord out = kolsky::io::read_run_hdf5(path);
  EXPECT_EQ(out.meta, rec.meta);  // meta_json is the source of truth, defaults only in attributes
  EXPECT_TRUE(out.probes.empty());
}

TEST(IoHdf5Run, FailureThrowsNamingPathAndLeavesNoFile) {
  TempDir dir;
  const std::string missing_dir_path = dir.file("no_such_dir/run.h5");
  try {
    kolsky::io::write_run_hdf5(missing_dir_path, sample_run());
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing_dir_path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(missing_dir_path));
  EXPECT_EQ(dir.n_entries(), 0u);
}

TEST(IoHdf5Run, InvalidRecordKeepsExistingFileAndLeavesNoTemporary) {
  TempDir dir;
  const std::string path = dir.file("run.h5");
  kolsky::io::write_run_hdf5(path, sample_run());
  RunRecord bad = sample_run();
  bad.probes[1].t.push_back(3e-6);  // t and value lengths now differ
  EXPECT_THROW(kolsky::io::write_run_hdf5(path, bad), std::runtime_error);
  bad = sample_run();
  bad.probes.push_back(bad.probes.front());  // duplicate name
  EXPECT_THROW(kolsky::io::write_run_hdf5(path, bad), std::runtime_error);
  bad = sample_run();
  bad.probes[0].name = "bad/name";
  EXPECT_THROW(kolsky::io::write_run_hdf5(path, bad), std::runtime_error);
  EXPECT_EQ(dir.n_entries(), 1u);
  EXPECT_EQ(kolsky::io::read_run_hdf5(path).meta, sample_run().meta);
}

TEST(IoHdf5Run, ReadingMissingOrForeignFileThrowsNamingPath) {
  TempDir dir;
  const std::string missing = dir.file("missing.h5");
  const std::string not_hdf5 = dir.file("text.h5");
  write_text(not_hdf5, "not an HDF5 file\n");
  for (const std::string& path : {missing, not_hdf5}) {
    try {
      kolsky::io::read_run_hdf5(path);
      ADD_FAILURE() << "expected std::runtime_error for " << path;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

TEST(IoCsv, RoundTripWithHeaderAndComment) {
  TempDir dir;
  CsvTable t;
  t.header = {"strain", "stress_mpa", "rate"};
  t.columns = {{0.0, 0.01, 0.02}, {0.0, 12.345678901, -3.5e-7}, {1500.0, 1.0e12, 0.1}};
  const std::string path = dir.file("table.csv");
  kolsky::io::write_csv(path, t, "digitized from Fig. 4.7\nsecond comment line");
  const CsvTable back = kolsky::io::read_csv(path);
  EXPECT_EQ(back.header, t.header);
  ASSERT_EQ(back.columns.size(), 3u);
  ASSERT_EQ(back.rows(), 3u);
  for (size_t c = 0; c < 3; ++c)
    for (size_t r = 0; r < 3; ++r)  // %.10g keeps 10 significant digits
      EXPECT_NEAR(back.columns[c][r], t.columns[c][r], 1e-9 * std::abs(t.columns[c][r]));
  EXPECT_EQ(&back.column("rate"), &back.columns[2]);
  std::ifstream f(path);
  std::string first;
  std::getline(f, first);
  EXPECT_EQ(first, "# digitized from Fig. 4.7");
}

TEST(IoCsv, HeaderlessNumericFileHasNoHeader) {
  TempDir dir;
  const std::string path = dir.file("plain.csv");
  write_text(path, "1, 2\n+3.5 ,-4e-3\nnan, inf\n");
  const CsvTable t = kolsky::io::read_csv(path);
  EXPECT_TRUE(t.header.empty());
  ASSERT_EQ(t.rows(), 3u);
  EXPECT_DOUBLE_EQ(t.columns[0][1], 3.5);
  EXPECT_DOUBLE_EQ(t.columns[1][1], -4e-3);
  EXPECT_TRUE(std::isnan(t.columns[0][2]));
  EXPECT_TRUE(std::isinf(t.columns[1][2]));
  EXPECT_THROW(t.column("x"), std::out_of_range);
}

TEST(IoCsv, CommentAndBlankLinesAreSkippedAndHeaderDetected) {
  TempDir dir;
  const std::string path = dir.file("commented.csv");
  write_text(path, "# source: Sec. 4.4\r\n\r\n  # indented comment\r\nx, y\r\n0,1\r\n# mid\r\n2,3\r\n");
  const CsvTable t = kolsky::io::read_csv(path);
  EXPECT_EQ(t.header, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(t.column("y"), (std::vector<double>{1.0, 3.0}));
}

TEST(IoCsv, RaggedRowNamesFileAndLine) {
  TempDir dir;
  const std::string path = dir.file("ragged.csv");
  write_text(path, "# comment\nx,y\n1,2\n3\n");
  try {
    kolsky::io::read_csv(path);
    FAIL() << "expected InputError";
  } catch (const kolsky::InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.path(), "line 4");
    EXPECT_NE(e.rule().find("1 cells"), std::string::npos) << e.what();
  }
}

TEST(IoCsv, NonNumericCellNamesColumn) {
  TempDir dir;
  const std::string path = dir.file("bad.csv");
  write_text(path, "x,y\n1,2\n3,abc\n");
  try {
    kolsky::io::read_csv(path);
    FAIL() << "expected InputError";
  } catch (const kolsky::InputError& e) {
    EXPECT_EQ(e.path(), "line 3");
    EXPECT_NE(e.rule().find("'y'"), std::string::npos) << e.what();
    EXPECT_NE(e.rule().find("abc"), std::string::npos) << e.what();
  }
}

TEST(IoCsv, MissingAndEmptyFilesAreInputErrors) {
  TempDir dir;
  try {
    kolsky::io::read_csv(dir.file("missing.csv"));
    FAIL() << "expected InputError";
  } catch (const kolsky::InputError& e) {
    EXPECT_EQ(e.rule(), "cannot open: No such file or directory");
  }
  try {  // a folder opens as a stream on Linux and reads as empty: say what it is
    kolsky::io::read_csv(dir.str());
    FAIL() << "expected InputError";
  } catch (const kolsky::InputError& e) {
    EXPECT_EQ(e.rule(), "is a directory, not a CSV file");
  }
  const std::string empty = dir.file("empty.csv");
  write_text(empty, "# only a comment\n\n");
  EXPECT_THROW(kolsky::io::read_csv(empty), kolsky::InputError);
}

TEST(IoCsv, MissingColumnListsAvailableOnes) {
  CsvTable t;
  t.header = {"strain", "stress"};
  t.columns = {{0.0}, {1.0}};
  try {
    t.column("time");
    FAIL() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'time'"), std::string::npos) << what;
    EXPECT_NE(what.find("strain, stress"), std::string::npos) << what;
  }
}

TEST(IoCsv, WriterRejectsInconsistentTables) {
  TempDir dir;
  CsvTable t;
  t.header = {"a", "b"};
  t.columns = {{1.0, 2.0}, {3.0}};
  EXPECT_THROW(kolsky::io::write_csv(dir.file("x.csv"), t), std::invalid_argument);
  t.columns = {{1.0}, {3.0}};
  t.header = {"a,b", "c"};
  EXPECT_THROW(kolsky::io::write_csv(dir.file("x.csv"), t), std::invalid_argument);
  t.header = {"1", "2"};  // would be read back as data
  EXPECT_THROW(kolsky::io::write_csv(dir.file("x.csv"), t), std::invalid_argument);
  EXPECT_EQ(dir.n_entries(), 0u);
}
