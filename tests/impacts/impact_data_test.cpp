// Tests for core/impacts/src/impact_data.cpp: MAT v5 files of impacts through
// libmatio, written by the tests themselves (the dataset is never committed)
// and, where ../shared/data/mcube/ exists, the shared training file. The
// values a file holds are checked against scipy.io.loadmat's reading
// (tests/impacts/read_mat.py), an independent reader.
#include <gtest/gtest.h>
#include <matio.h>
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_data.hpp"
#include "planarbench/impacts/mat_preflight.hpp"
#include "synthetic_impacts.hpp"

namespace fs = std::filesystem;

namespace {

fs::path work_dir() {
  const fs::path d = fs::path(PB_WORK_DIR) / "impact_data";
  fs::create_directories(d);
  return d;
}

pb::ImpactSet small_set() {
  return pb::test::synthetic_impacts(12, 7, [](const pb::ImpactState& s) {
    pb::ImpactState after = s;
    after.velocity_mps.y() *= -0.5;
    return after;
  });
}

// InputError's message for reading `path`
std::string refusal(const fs::path& path) {
  try {
    (void)pb::read_impacts(path);
  } catch (const pb::InputError& e) {
    return e.what();
  }
  return "(read without error)";
}

// a MAT file with one struct `data` holding the given fields, of doubles
// (0.5 each) but for the field named `int32_field`, of int32 zeros
void write_struct(const fs::path& path,
                  const std::vector<std::pair<const char*, std::vector<std::size_t>>>& fields,
                  const std::string& int32_field = "") {
  mat_t* mat = Mat_CreateVer(path.string().c_str(), nullptr, MAT_FT_MAT5);
  ASSERT_NE(mat, nullptr);
  std::vector<const char*> names;
  for (const auto& f : fields) names.push_back(f.first);
  names.push_back(nullptr);
  std::size_t one[2] = {1, 1};
  matvar_t* data = Mat_VarCreateStruct2("data", 2, one, names.data());
  std::vector<std::vector<double>> storage;
  std::vector<std::vector<std::int32_t>> ints;
  for (const auto& [name, dims] : fields) {
    std::size_t count = 1;
    for (const std::size_t k : dims) count *= k;
    std::vector<std::size_t> d = dims;
    const int rank = static_cast<int>(d.size());
    if (name == int32_field) {
      ints.emplace_back(count, 0);
      Mat_VarSetStructFieldByName(data, name, 0,
                                  Mat_VarCreate(name, MAT_C_INT32, MAT_T_INT32, rank, d.data(),
                                                ints.back().data(), 0));
    } else {
      storage.emplace_back(count, 0.5);
      Mat_VarSetStructFieldByName(data, name, 0,
                                  Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, rank, d.data(),
                                                storage.back().data(), 0));
    }
  }
  ASSERT_EQ(Mat_VarWrite(mat, data, MAT_COMPRESSION_NONE), 0);
  Mat_VarFree(data);
  Mat_Close(mat);
}

}  // namespace

TEST(ImpactData, WhatIsWrittenIsReadBackBitForBit) {
  pb::ImpactSet set = small_set();
  for (std::size_t i = 0; i < set.size(); ++i) {
    std::array<double, 18> row{};
    for (std::size_t j = 0; j < 18; ++j) row[j] = 0.01 * static_cast<double>(i * 18 + j) - 1.0 / 3.0;
    set.models.push_back(row);
  }
  const fs::path file = work_dir() / "round_trip.mat";
  pb::write_impacts(file, set);
  const pb::ImpactSet back = pb::read_impacts(file);
  ASSERT_EQ(back.size(), set.size());
  EXPECT_EQ(back.pre, set.pre);
  EXPECT_EQ(back.post, set.post);
  EXPECT_EQ(back.drop, set.drop);
  EXPECT_EQ(back.models, set.models);
  EXPECT_EQ(back.sha256.size(), 64u);
  EXPECT_EQ(back.path, file.string());
}

TEST(ImpactData, ScipyReadsTheWrittenFileAsWritten) {
  // scipy.io.loadmat is an independent MAT reader: the file is a standard
  // MAT v5 file, not one only libmatio understands
  const pb::ImpactSet set = small_set();
  const fs::path file = work_dir() / "for_scipy.mat";
  pb::write_impacts(file, set);
  const fs::path out = work_dir() / "for_scipy.json";
  const std::string cmd = std::string(PB_PYTHON) + " " + PB_SOURCE_DIR + "/tests/impacts/read_mat.py " +
                          file.string() + " > " + out.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out));
  ASSERT_EQ(j.at("states_i").size(), set.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    for (std::size_t c = 0; c < 6; ++c) {
      EXPECT_EQ(j.at("states_i").at(i).at(c).get<double>(), set.pre[i][c]);  // exact: repr round-trips
      EXPECT_EQ(j.at("states_f").at(i).at(c).get<double>(), set.post[i][c]);
    }
  }
  EXPECT_FALSE(j.at("has_v_models").get<bool>());
}

TEST(ImpactData, TheSharedTrainingFileIsReadAsScipyReadsIt) {
  const fs::path shared = fs::path(PB_SOURCE_DIR) / "../shared/data/mcube/ellipse_impacts_train.mat";
  if (!fs::exists(shared)) GTEST_SKIP() << shared << " is not on this machine";
  const pb::ImpactSet set = pb::read_impacts(shared);
  ASSERT_EQ(set.size(), 1146u);  // the README's count
  ASSERT_EQ(set.models.size(), 1146u);
  const fs::path out = work_dir() / "shared.json";
  const std::string cmd = std::string(PB_PYTHON) + " " + PB_SOURCE_DIR + "/tests/impacts/read_mat.py " +
                          shared.string() + " > " + out.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out));
  for (std::size_t i = 0; i < set.size(); i += 97) {
    for (std::size_t c = 0; c < 6; ++c) {
      EXPECT_EQ(j.at("states_i").at(i).at(c).get<double>(), set.pre[i][c]);
      EXPECT_EQ(j.at("states_f").at(i).at(c).get<double>(), set.post[i][c]);
    }
    EXPECT_EQ(j.at("drop").at(i).get<double>(), set.drop[i]);
    EXPECT_EQ(j.at("v_models").at(i).at(17).get<double>(), set.models[i][17]);
  }
  EXPECT_EQ(j.at("sha256").get<std::string>(), set.sha256);  // hashlib's sha256 of the bytes
}

TEST(ImpactData, AFileOfAnotherLayoutIsRefusedNamingTheVariable) {
  const fs::path dir = work_dir();
  // not a MAT file at all
  std::ofstream(dir / "text.mat") << "hello\n";
  EXPECT_NE(refusal(dir / "text.mat").find("--data: is not a MAT v5 file (no MATLAB 5.0 header)"), std::string::npos) << refusal(dir / "text.mat");
  // no such file
  EXPECT_NE(refusal(dir / "missing.mat").find("is not a readable file"), std::string::npos);
  // states_i with 5 columns
  write_struct(dir / "five.mat", {{"states_i", {4, 5}}, {"states_f", {4, 6}}, {"n", {4, 3}}, {"d", {4, 3}}, {"drop", {1, 4}}});
  const std::string five = refusal(dir / "five.mat");
  EXPECT_NE(five.find("data.states_i"), std::string::npos) << five;
  EXPECT_NE(five.find("N x 6"), std::string::npos) << five;
  EXPECT_NE(five.find("4 x 5"), std::string::npos) << five;
  // states_f missing
  write_struct(dir / "nof.mat", {{"states_i", {4, 6}}, {"n", {4, 3}}, {"d", {4, 3}}, {"drop", {1, 4}}});
  const std::string nof = refusal(dir / "nof.mat");
  EXPECT_NE(nof.find("data.states_f"), std::string::npos) << nof;
  EXPECT_NE(nof.find("missing"), std::string::npos) << nof;
  // drop of the wrong length
  write_struct(dir / "drop.mat", {{"states_i", {4, 6}}, {"states_f", {4, 6}}, {"n", {4, 3}}, {"d", {4, 3}}, {"drop", {1, 3}}});
  EXPECT_NE(refusal(dir / "drop.mat").find("data.drop"), std::string::npos) << refusal(dir / "drop.mat");
  // no struct named data
  {
    mat_t* mat = Mat_CreateVer((dir / "nodata.mat").string().c_str(), nullptr, MAT_FT_MAT5);
    double v[1] = {1.0};
    std::size_t dims[2] = {1, 1};
    matvar_t* x = Mat_VarCreate("x", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, v, 0);
    Mat_VarWrite(mat, x, MAT_COMPRESSION_NONE);
    Mat_VarFree(x);
    Mat_Close(mat);
  }
  const std::string nodata = refusal(dir / "nodata.mat");
  EXPECT_NE(nodata.find("data"), std::string::npos) << nodata;
  EXPECT_NE(nodata.find("states_i, states_f"), std::string::npos) << nodata;
}

TEST(ImpactData, ANonFiniteStateIsRefusedWithItsRowAndColumn) {
  pb::ImpactSet set = small_set();
  set.post[3][4] = std::nan("");
  const fs::path file = work_dir() / "nan.mat";
  pb::write_impacts(file, set);
  const std::string why = refusal(file);
  EXPECT_NE(why.find("data.states_f"), std::string::npos) << why;
  EXPECT_NE(why.find("row 4 column 5"), std::string::npos) << why;
}

TEST(ImpactData, AMisshapenStatesMatrixIsNamedForWhatItIs) {
  // issue 35 item 16: a transposed states_i said "must be 6 x 6 (got 6 x 20)",
  // a 3-D one "missing", int32 data "got class 12"
  const fs::path dir = work_dir();
  const std::vector<std::pair<const char*, std::vector<std::size_t>>> rest = {
      {"states_f", {20, 6}}, {"n", {20, 3}}, {"d", {20, 3}}, {"drop", {1, 20}}};
  auto with_states_i = [&](std::vector<std::size_t> dims) {
    auto fields = rest;
    fields.insert(fields.begin(), {"states_i", std::move(dims)});
    return fields;
  };
  write_struct(dir / "transposed.mat", with_states_i({6, 20}));
  const std::string transposed = refusal(dir / "transposed.mat");
  EXPECT_NE(transposed.find("data.states_i: must be N x 6"), std::string::npos) << transposed;
  EXPECT_NE(transposed.find("got 6 x 20: transposed?"), std::string::npos) << transposed;

  write_struct(dir / "three_d.mat", with_states_i({20, 6, 2}));
  const std::string three_d = refusal(dir / "three_d.mat");
  EXPECT_NE(three_d.find("data.states_i: must be a 2-D matrix"), std::string::npos) << three_d;
  EXPECT_NE(three_d.find("got 3 dimensions: 20 x 6 x 2"), std::string::npos) << three_d;

  write_struct(dir / "int32.mat", with_states_i({20, 6}), "states_i");
  const std::string int32 = refusal(dir / "int32.mat");
  EXPECT_NE(int32.find("data.states_i: must be a real double matrix"), std::string::npos) << int32;
  EXPECT_NE(int32.find("(got int32)"), std::string::npos) << int32;
}

TEST(ImpactData, AStateNoDropCouldHaveIsRefusedWithItsRowAndColumn) {
  // issue 35 items 10 and 16: one 1e308 row was read and then refused as "no
  // angle convention conserves ..." without a row; impacts at 2.9e5 m/s ran
  const fs::path file = work_dir() / "limits.mat";
  struct Damage {
    bool post;
    std::size_t column;
    double value;
    const char* said;
  };
  for (const Damage& d : {Damage{false, 4, 1e308, "data.states_i: row 4 column 5 (y') is 1e+308 m/s"},
                          Damage{true, 3, -2.9e5, "data.states_f: row 4 column 4 (x') is -290000 m/s"},
                          Damage{false, 5, 2e4, "row 4 column 6 (theta') is 20000 rad/s"},
                          Damage{false, 0, 150.0, "row 4 column 1 (x) is 150 m"}}) {
    pb::ImpactSet set = small_set();
    (d.post ? set.post : set.pre)[3][d.column] = d.value;
    pb::write_impacts(file, set);
    const std::string why = refusal(file);
    EXPECT_NE(why.find(d.said), std::string::npos) << why;
    EXPECT_NE(why.find("must be a finite number within"), std::string::npos) << why;
  }
  // the limits are 20 to 200 times the MCube drops': 99 m/s is read
  pb::ImpactSet fast = small_set();
  fast.pre[3][3] = 99.0;
  pb::write_impacts(file, fast);
  EXPECT_NO_THROW((void)pb::read_impacts(file));
}

TEST(ImpactData, AnImpactThatChangesNothingIsRefused) {
  // issue 35 item 10: a file whose every impact has post = pre scored "n/a"
  // everywhere and exited 0
  const fs::path file = work_dir() / "no_impact.mat";
  pb::ImpactSet same = small_set();
  same.post = same.pre;
  pb::write_impacts(file, same);
  const std::string why = refusal(file);
  EXPECT_NE(why.find("data.states_f: row 1: the velocities after the impact equal those before"),
            std::string::npos)
      << why;
}

// ---- mat_preflight.cpp: a MAT v5 file's structure walked before libmatio ----
namespace {

// MAT v5 bytes (little-endian), written here apart from any MAT library
struct MatWriter {
  std::string bytes = [] {
    std::string h = "MATLAB 5.0 MAT-file, written by impact_data_test";
    h.resize(116, ' ');
    h += std::string(8, '\0');
    h += std::string("\x00\x01", 2) + "IM";
    return h;
  }();
  static std::string u32(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }
  // an element: tag, data, padding to 8 bytes (`claimed` overrides the count)
  static std::string element(std::uint32_t type, const std::string& data, std::int64_t claimed = -1) {
    std::string e;
    e.append(u32(type));
    e.append(u32(static_cast<std::uint32_t>(claimed < 0 ? static_cast<std::int64_t>(data.size()) : claimed)));
    e.append(data);
    e.append((8 - e.size() % 8) % 8, '\0');
    return e;
  }
  // a matrix's header: flags, dimensions, name
  static std::string header(int cls, const std::vector<std::int32_t>& dims, const std::string& name) {
    std::string d;
    for (const auto k : dims) d.append(u32(static_cast<std::uint32_t>(k)));
    std::string flags = u32(static_cast<std::uint32_t>(cls));
    flags.append(u32(0));
    std::string out = element(6, flags);
    out.append(element(5, d));
    out.append(element(1, name));
    return out;
  }
};

std::string struct_of(std::size_t fields, std::int64_t claimed_names = -1) {
  std::string names;
  for (std::size_t f = 0; f < fields; ++f) {
    // "f<number>", NUL-padded to 8 bytes
    char n[8] = {};
    std::snprintf(n, sizeof n, "f%zu", f);
    names.append(n, sizeof n);
  }
  std::string body = MatWriter::header(2, {1, 1}, "data");
  body.append(MatWriter::element(5, MatWriter::u32(8)));
  body.append(MatWriter::element(1, names, claimed_names));
  for (std::size_t f = 0; f < fields; ++f) body.append(MatWriter::element(14, ""));
  return MatWriter::element(14, body);
}

}  // namespace

TEST(MatPreflight, AStructOfTooManyFieldsIsRefusedBeforeLibmatioAllocates) {
  // found by fuzz_impact_data: a field-name element claiming 4.7e8 names made
  // Mat_VarReadInfo allocate 7.5 GB
  MatWriter ok;
  ok.bytes += struct_of(5);
  EXPECT_EQ(pb::mat_v5_problem(ok.bytes).what, "");
  MatWriter many;
  many.bytes += struct_of(65);
  const pb::MatProblem p = pb::mat_v5_problem(many.bytes);
  EXPECT_EQ(p.variable, "data");
  EXPECT_NE(p.what.find("claims a struct of 1 x 1 elements of 65 fields: at most 64 fields"),
            std::string::npos)
      << p.what;
  MatWriter claims;
  claims.bytes += struct_of(2, 4000000000LL);
  const pb::MatProblem c = pb::mat_v5_problem(claims.bytes);
  EXPECT_NE(c.what.find("is truncated or damaged: at byte 200: an element claims 4000000000 bytes"),
            std::string::npos)
      << c.what;
}

TEST(MatPreflight, AMatrixOfMoreValuesThanAFileOfImpactsHoldsIsRefused) {
  MatWriter w;
  w.bytes += MatWriter::element(14, MatWriter::header(6, {10000000, 6}, "v_models"));
  const pb::MatProblem p = pb::mat_v5_problem(w.bytes);
  EXPECT_EQ(p.variable, "v_models");
  EXPECT_NE(p.what.find("claims 10000000 x 6 values: a file holds at most 100000 impacts"),
            std::string::npos)
      << p.what;
}

TEST(MatPreflight, ACompressedVariableInflatingPastTheCapIsRefused) {
  // 70 MB of zeros deflate to ~70 kB: inflated in 64 kB pieces, stopped at 64 MB
  const std::string zeros(70u << 20, '\0');
  uLongf size = compressBound(static_cast<uLong>(zeros.size()));
  std::string z(size, '\0');
  ASSERT_EQ(compress(reinterpret_cast<Bytef*>(z.data()), &size,
                     reinterpret_cast<const Bytef*>(zeros.data()), static_cast<uLong>(zeros.size())),
            Z_OK);
  z.resize(size);
  MatWriter w;
  w.bytes.append(MatWriter::u32(15));
  w.bytes.append(MatWriter::u32(static_cast<std::uint32_t>(z.size())));
  w.bytes.append(z);
  const pb::MatProblem p = pb::mat_v5_problem(w.bytes);
  EXPECT_NE(p.what.find("a compressed variable inflates past 64 MB"), std::string::npos) << p.what;
}

TEST(MatPreflight, NestingPastTheLimitIsRefused) {
  std::string leaf = MatWriter::header(6, {1, 1}, "");
  leaf.append(MatWriter::element(9, std::string(8, '\0')));
  std::string inner = MatWriter::element(14, leaf);
  for (int k = 0; k < 12; ++k) {
    std::string cell = MatWriter::header(1, {1, 1}, k == 11 ? "data" : "");
    cell.append(inner);
    inner = MatWriter::element(14, cell);
  }
  MatWriter w;
  w.bytes += inner;
  const pb::MatProblem p = pb::mat_v5_problem(w.bytes);
  EXPECT_NE(p.what.find("is nested past 8 levels"), std::string::npos) << p.what;
  EXPECT_EQ(p.variable.rfind("data{1}", 0), 0u) << p.variable;
}
