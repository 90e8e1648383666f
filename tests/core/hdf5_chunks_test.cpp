// The chunk writer of the results file (core/src/internal/hdf5_chunks.hpp)
// against its oracle, the HDF5 library's own shuffle + deflate filters: a
// dataset written by H5Dwrite (the library filters) and the same data written
// through our writer must hold the same chunk bytes (H5Dread_chunk reads them
// raw), whatever the writer's thread count, and a dataset written by us must
// read back, through the library's filter pipeline, to the values given.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "../../core/src/internal/hdf5_chunks.hpp"
#include "../../core/src/internal/hdf5_datasets.hpp"

namespace {

namespace fs = std::filesystem;
using pb::internal::ChunkWriter;
using pb::internal::Hid;
using pb::internal::kChunkRows;
using pb::internal::kDeflateLevel;
using pb::internal::shuffle_bytes;

// prefix + k; appended, not operator+, which trips GCC 12's -Wrestrict false
// positive at -O3 (GCC PR 105329)
std::string dataset_name(const char* prefix, std::size_t k) {
  std::string s(prefix);
  s.append("_").append(std::to_string(k));
  return s;
}

TEST(ShuffleBytes, GroupsByteJOfEveryElement) {
  // three 2-byte elements a, b, c: the low bytes first, then the high bytes
  const unsigned char in[6] = {0xa0, 0xa1, 0xb0, 0xb1, 0xc0, 0xc1};
  unsigned char out[6] = {};
  shuffle_bytes(in, 6, 2, out);
  const unsigned char want[6] = {0xa0, 0xb0, 0xc0, 0xa1, 0xb1, 0xc1};
  EXPECT_EQ(0, std::memcmp(out, want, 6));
}

TEST(ShuffleBytes, TrailingPartialElementIsCopied) {
  // two 3-byte elements and 2 bytes left over (H5Zshuffle.c copies them last)
  const unsigned char in[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  unsigned char out[8] = {};
  shuffle_bytes(in, 8, 3, out);
  const unsigned char want[8] = {1, 4, 2, 5, 3, 6, 7, 8};
  EXPECT_EQ(0, std::memcmp(out, want, 8));
}

class Hdf5Chunks : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pb_hdf5_chunks_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    file_ = pb::internal::owned_file(
        H5Fcreate((dir_ / "c.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "/",
        "cannot create the file");
  }
  void TearDown() override {
    file_.close("/");
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // a dataset written by the library's own filters (plain H5Dwrite)
  Hid library_written(const char* name, hid_t type, int rank, const hsize_t* dims,
                      const void* buf) {
    Hid space = pb::internal::owned_space(H5Screate_simple(rank, dims, nullptr), name, "space");
    Hid dcpl = pb::internal::dataset_properties(rank, dims, name);
    Hid d = pb::internal::owned_dataset(
        H5Dcreate2(file_.get(), name, type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
        name, "create");
    EXPECT_GE(H5Dwrite(d.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf), 0);
    return d;
  }

  // chunk i of d, as stored (filtered); its filter mask must be 0
  static std::vector<unsigned char> stored_chunk(hid_t d, hsize_t i) {
    const hsize_t offset[2] = {i * kChunkRows, 0};
    hsize_t size = 0;
    EXPECT_GE(H5Dget_chunk_storage_size(d, offset, &size), 0);
    std::vector<unsigned char> out(size);
    uint32_t mask = 99;
    EXPECT_GE(H5Dread_chunk(d, H5P_DEFAULT, offset, &mask, out.data()), 0);
    EXPECT_EQ(mask, 0u) << "chunk " << i << " skipped a filter";
    return out;
  }

  // writes buf as the library does and through a writer of 1 and of 3
  // threads; every chunk of ours must equal the library's
  void expect_same_chunks_as_library(const char* name, hid_t type, int rank, const hsize_t* dims,
                                     const void* buf) {
    Hid lib = library_written(name, type, rank, dims, buf);
    const hsize_t n = (dims[0] + kChunkRows - 1) / kChunkRows;
    for (int threads : {1, 3}) {
      const std::string ours_name = dataset_name(name, static_cast<std::size_t>(threads));
      {
        // our encoder, called directly: it must take the data (true), or
        // the comparison below would only compare the library with itself
        Hid space = pb::internal::owned_space(H5Screate_simple(rank, dims, nullptr), ours_name,
                                              "space");
        Hid dcpl = pb::internal::dataset_properties(rank, dims, ours_name);
        Hid d = pb::internal::owned_dataset(H5Dcreate2(file_.get(), ours_name.c_str(), type,
                                                       space.get(), H5P_DEFAULT, dcpl.get(),
                                                       H5P_DEFAULT),
                                            ours_name, "create");
        ChunkWriter writer(threads);
        EXPECT_TRUE(pb::internal::write_encoded_chunks(d, type, type, rank, dims, buf, &writer,
                                                       ours_name))
            << name << ": the data did not take the encoder";
        d.close(ours_name);  // the writer holds a handle of its own
        writer.finish();
      }
      Hid ours = pb::internal::owned_dataset(H5Dopen2(file_.get(), ours_name.c_str(), H5P_DEFAULT),
                                             ours_name, "open");
      for (hsize_t i = 0; i < n; ++i) {
        EXPECT_EQ(stored_chunk(ours.get(), i), stored_chunk(lib.get(), i))
            << name << " chunk " << i << " with " << threads << " threads";
      }
    }
  }

  fs::path dir_;
  Hid file_;
};

// smooth values (a trajectory) and noise (incompressible), 2.5 chunks
std::vector<double> sample_values(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = i % 3 == 0 ? noise(rng) : 0.5 * 9.81 * (1e-4 * static_cast<double>(i)) * 1e-4 *
                                         static_cast<double>(i);
  }
  return v;
}

TEST_F(Hdf5Chunks, DoublesMatchTheLibrarysFilters) {
  const std::vector<double> v = sample_values(2 * kChunkRows + kChunkRows / 2, 1);
  const hsize_t dims[1] = {v.size()};
  expect_same_chunks_as_library("d1", H5T_IEEE_F64LE, 1, dims, v.data());
}

TEST_F(Hdf5Chunks, RowsOfTwoDoublesMatchTheLibrarysFilters) {
  const std::vector<double> v = sample_values(2 * (kChunkRows + 7), 2);
  const hsize_t dims[2] = {v.size() / 2, 2};
  expect_same_chunks_as_library("d2", H5T_IEEE_F64LE, 2, dims, v.data());
}

struct Row {
  double t;
  char name[32];
  double xy[2];
};

TEST_F(Hdf5Chunks, CompoundRowsMatchTheLibrarysFilters) {
  using pb::internal::FieldKind;
  const pb::internal::TableLayout layout{
      sizeof(Row),
      {{"t", FieldKind::f8, offsetof(Row, t), "s"},
       {"name", FieldKind::name, offsetof(Row, name), ""},
       {"xy", FieldKind::f8x2, offsetof(Row, xy), "m"}}};
  std::vector<Row> rows(kChunkRows + 100, Row{});
  const std::vector<double> v = sample_values(3 * rows.size(), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].t = v[3 * i];
    std::snprintf(rows[i].name, sizeof rows[i].name, "body_%zu", i % 5);
    rows[i].xy[0] = v[3 * i + 1];
    rows[i].xy[1] = v[3 * i + 2];
  }
  Hid file_type = pb::internal::table_type(layout, true, "rows");
  Hid mem_type = pb::internal::table_type(layout, false, "rows");
  // the record has no padding, so memory bytes are file bytes (the direct path)
  ASSERT_GT(H5Tequal(file_type.get(), mem_type.get()), 0);
  const hsize_t dims[1] = {rows.size()};
  expect_same_chunks_as_library("rows", file_type.get(), 1, dims, rows.data());

  // written by our path, read back through the library's filters
  {
    ChunkWriter writer(2);
    pb::internal::write_table(file_.get(), "ours", layout, rows.data(), rows.size(), &writer);
    writer.finish();
  }
  const auto back = pb::internal::read_table<Row>(file_.get(), "ours", layout);
  ASSERT_EQ(back.size(), rows.size());
  EXPECT_EQ(0, std::memcmp(back.data(), rows.data(), rows.size() * sizeof(Row)));
}

TEST_F(Hdf5Chunks, WrittenDoublesReadBackBitForBitWithAnyThreadCount) {
  const std::vector<double> v = sample_values(6 * (3 * kChunkRows + 1), 4);
  for (int threads : {1, 2, 5}) {
    const std::string name = dataset_name("v", static_cast<std::size_t>(threads));
    {
      ChunkWriter writer(threads);
      pb::internal::write_double_dataset(file_.get(), name.c_str(), v, 6, "m", &writer);
      writer.finish();
    }
    const auto back = pb::internal::read_double_dataset(file_.get(), name.c_str(), 6);
    ASSERT_EQ(back.size(), v.size());
    EXPECT_EQ(0, std::memcmp(back.data(), v.data(), v.size() * sizeof(double))) << threads;
  }
}

TEST_F(Hdf5Chunks, ManyDatasetsInFlightAreWrittenInFull) {
  // more datasets queued than threads, of unequal sizes, some written while
  // others are still compressing: each reads back whole
  std::vector<std::vector<double>> values;
  for (unsigned k = 0; k < 12; ++k) values.push_back(sample_values((k + 2) * kChunkRows + k, k));
  {
    ChunkWriter writer(2);
    for (std::size_t k = 0; k < values.size(); ++k) {
      const std::string name = dataset_name("m", k);
      pb::internal::write_double_dataset(file_.get(), name.c_str(), values[k], 0, "m", &writer);
    }
    writer.finish();
  }
  for (std::size_t k = 0; k < values.size(); ++k) {
    const std::string name = dataset_name("m", k);
    EXPECT_EQ(pb::internal::read_double_dataset(file_.get(), name.c_str(), 0), values[k]) << k;
  }
}

TEST_F(Hdf5Chunks, VariableLengthStringsTakeTheLibrarysPath) {
  // pointers in memory: never encoded as bytes; the library writes them
  Hid type = pb::internal::vlen_utf8_type("s");
  std::vector<std::string> text(kChunkRows + 3);
  std::vector<const char*> ptrs;
  for (std::size_t i = 0; i < text.size(); ++i) text[i] = "row " + std::to_string(i);
  for (const auto& s : text) ptrs.push_back(s.c_str());
  const hsize_t n = text.size();
  {
    // the encoder itself refuses them
    const hsize_t dims[1] = {n};
    Hid space = pb::internal::owned_space(H5Screate_simple(1, dims, nullptr), "s0", "space");
    Hid dcpl = pb::internal::dataset_properties(1, dims, "s0");
    Hid d0 = pb::internal::owned_dataset(H5Dcreate2(file_.get(), "s0", type.get(), space.get(),
                                                    H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                                         "s0", "create");
    ChunkWriter writer(2);
    EXPECT_FALSE(pb::internal::write_encoded_chunks(d0, type.get(), type.get(), 1, dims,
                                                    ptrs.data(), &writer, "s0"));
    writer.finish();
  }
  ChunkWriter writer(2);
  Hid d = pb::internal::create_and_write(file_.get(), "s", type.get(), type.get(), 1, &n,
                                         ptrs.data(), &writer);
  writer.finish();
  std::vector<char*> back(n, nullptr);
  ASSERT_GE(H5Dread(d.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, back.data()), 0);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_NE(back[i], nullptr);
    EXPECT_EQ(std::string(back[i]), text[i]);
  }
  Hid space = pb::internal::owned_space(H5Dget_space(d.get()), "s", "space");
  H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, back.data());
}

}  // namespace
