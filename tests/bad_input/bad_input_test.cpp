// Tests for apps/ (the planarbench command line) on bad input: every entry of
// tests/data/bad/corpus.toml is given to the real planarbench binary, which
// must refuse it with exit code 2 and ONE line on stderr naming the file, the
// line, the field and what is allowed, and must write nothing (issue 7; the
// rule is in tests/data/bad/README.md).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <toml++/toml.h>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kDataDir = fs::path(PB_TEST_DATA_DIR) / "bad";
const fs::path kCorpus = kDataDir / "corpus.toml";
const std::string kPrefix = "planarbench: error: ";

// ---- the corpus ------------------------------------------------------------------

struct Entry {
  std::string name;
  std::string what;
  std::vector<std::string> args;    // with placeholders, see corpus.toml
  int exit_code = -1;
  std::vector<std::string> expect;  // substrings of the one stderr line
  std::vector<std::string> setup;   // good_results, good_case, big_file, readonly_dir, damaged:KIND
};

// gtest prints parameters; the name says which entry it is
void PrintTo(const Entry& e, std::ostream* os) { *os << e.name; }

struct Corpus {
  std::vector<Entry> entries;
  std::string error;  // why the manifest could not be read, if it could not
};

std::vector<std::string> strings_of(const toml::table& t, const char* key, std::string& error,
                                    const std::string& where) {
  std::vector<std::string> out;
  const toml::node* n = t.get(key);
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr) {
    error += where + "." + key + ": not an array of strings\n";
    return out;
  }
  for (const auto& v : *a) {
    if (const auto* s = v.as_string()) {
      out.push_back(s->get());
    } else {
      error += where + "." + key + ": not an array of strings\n";
    }
  }
  return out;
}

// the manifest, read once; a malformed manifest is reported by a test, not a crash
const Corpus& corpus() {
  static const Corpus c = [] {
    Corpus out;
    toml::table doc;
    try {
      doc = toml::parse_file(kCorpus.string());
    } catch (const toml::parse_error& e) {
      out.error = kCorpus.string() + ": " + std::string(e.description());
      return out;
    }
    const toml::array* entries = doc["entry"].as_array();
    if (entries == nullptr) {
      out.error = kCorpus.string() + ": no [[entry]] tables";
      return out;
    }
    static const std::set<std::string> keys = {"name", "what", "args", "exit", "expect", "setup"};
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const std::string where = "entry[" + std::to_string(i) + "]";
      const toml::table* t = (*entries)[i].as_table();
      if (t == nullptr) {
        out.error += where + ": not a table\n";
        continue;
      }
      for (auto&& [k, v] : *t) {
        if (keys.count(std::string(k.str())) == 0) out.error += where + ": unknown key " + std::string(k.str()) + "\n";
      }
      Entry e;
      e.name = t->get_as<std::string>("name") ? t->get_as<std::string>("name")->get() : "";
      e.what = t->get_as<std::string>("what") ? t->get_as<std::string>("what")->get() : "";
      e.exit_code = t->get_as<int64_t>("exit") ? static_cast<int>(t->get_as<int64_t>("exit")->get()) : -1;
      e.args = strings_of(*t, "args", out.error, where);
      e.expect = strings_of(*t, "expect", out.error, where);
      e.setup = strings_of(*t, "setup", out.error, where);
      out.entries.push_back(std::move(e));
    }
    return out;
  }();
  return c;
}

bool valid_name(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
  });
}

// ---- the folder the tests work in ------------------------------------------------

// a folder of this process's own: ctest may run several test processes at once
const fs::path& work_root() {
  static const fs::path root = [] {
    const fs::path p = fs::path(PB_WORK_DIR) / ("run." + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
  }();
  return root;
}

// removes the work folder when every test passed (else it shows what happened)
class WorkFolderCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Passed()) return;
    std::error_code ec;
    fs::remove_all(work_root(), ec);
  }
};
[[maybe_unused]] const auto* const kCleanup =
    ::testing::AddGlobalTestEnvironment(new WorkFolderCleanup);

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// a stand-in for reports/web (the report reads its assets before the results
// file; the real uPlot is an npm package CI may not have)
const fs::path& web_dir() {
  static const fs::path dir = [] {
    const fs::path w = work_root() / "web";
    const fs::path u = w / "node_modules" / "uplot";
    write_file(u / "dist" / "uPlot.iife.min.js", "var uPlot = function () {};\n");
    write_file(u / "dist" / "uPlot.min.css", ".uplot {}\n");
    write_file(u / "LICENSE", "stand-in\n");
    write_file(u / "package.json", "{\"version\": \"0.0.0\"}\n");
    write_file(w / "report_template.html", "<html><body></body></html>\n");
    write_file(w / "report.js", "var page = 1;\n");
    write_file(w / "report.css", "body {}\n");
    return w;
  }();
  return dir;
}

struct Outcome {
  bool signalled = false;
  int signal = 0;
  bool timed_out = false;
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// runs planarbench with `args` in folder `cwd`, capturing both streams into
// files outside it (so they are not mistaken for files planarbench left)
Outcome run_planarbench(const std::vector<std::string>& args, const fs::path& cwd,
                        const std::string& tag) {
  const fs::path out_file = work_root() / (tag + ".stdout");
  const fs::path err_file = work_root() / (tag + ".stderr");
  std::vector<std::string> argv_s = {PB_EXE};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);

  const std::string web = web_dir().string();  // made here, not in the child
  Outcome o;
  const pid_t pid = ::fork();
  if (pid < 0) {
    o.err = std::string("fork failed: ") + std::strerror(errno);
    return o;
  }
  if (pid == 0) {
    // the child: its folder, its streams, the stand-in web folder, then exec
    if (::chdir(cwd.c_str()) != 0) ::_exit(126);
    const int fo = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int fe = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fo < 0 || fe < 0 || ::dup2(fo, 1) < 0 || ::dup2(fe, 2) < 0) ::_exit(126);
    ::setenv("PLANARBENCH_WEB_DIR", web.c_str(), 1);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  // a generous limit: every entry fails before any simulation, in well under
  // a second even under ASan; a hang is a failure, not a stuck CI job
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  while (true) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      o.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFSIGNALED(status)) {
    o.signalled = true;
    o.signal = WTERMSIG(status);
  } else if (WIFEXITED(status)) {
    o.exit_code = WEXITSTATUS(status);
  }
  o.out = read_file(out_file);
  o.err = read_file(err_file);
  return o;
}

// a valid results file to give check and report with a bad thresholds file
const fs::path& good_results() {
  static const fs::path p = [] {
    const fs::path f = work_root() / "good.h5";
    const Outcome o = run_planarbench(
        {"run", "--case", "falling_ball", "--engine", "analytic", "--quiet", "--out", f.string()},
        work_root(), "good_results");
    return o.exit_code == 0 && fs::exists(f) ? f : fs::path();
  }();
  return p;
}

// every file and folder under `dir` with its size: what planarbench must not change
// every entry of the folder: its type (not following links: a FIFO renamed
// over is a change) and a regular file's size
std::map<std::string, std::pair<int, std::uintmax_t>> listing(const fs::path& dir) {
  std::map<std::string, std::pair<int, std::uintmax_t>> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    std::error_code ec;
    const auto type = static_cast<int>(e.symlink_status(ec).type());
    const auto size = e.is_regular_file(ec) && !e.is_symlink(ec) ? e.file_size(ec) : 0;
    out[fs::relative(e.path(), dir).string()] = {type, size};
  }
  return out;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) {
    s.replace(at, from.size(), to);
  }
  return s;
}

// ---- one test per entry ------------------------------------------------------------

class BadInput : public ::testing::TestWithParam<Entry> {};

TEST_P(BadInput, IsRefusedWithOneClearLineAndNoFiles) {
  const Entry& e = GetParam();
  SCOPED_TRACE(e.name + ": " + e.what);

  // the entry's own empty folder and what its setup asks for
  const fs::path tmp = work_root() / e.name;
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  std::map<std::string, std::string> vars = {
      {"{data}", kDataDir.string()},       {"{testdata}", PB_TEST_DATA_DIR},
      {"{cases}", PB_CASES_DIR},           {"{tmp}", tmp.string()},
      {"{out}", (tmp / "out.h5").string()}, {"{good}", (tmp / "good.h5").string()},
      {"{big}", (tmp / "big.toml").string()}, {"{readonly}", (tmp / "readonly").string()},
      {"{case}", (tmp / "case.toml").string()}, {"{fifo}", (tmp / "fifo").string()},
      {"{damaged}", (tmp / "damaged.h5").string()},
      {"{fifolink}", (tmp / "fifolink").string()}, {"{dangling}", (tmp / "dangling").string()}};
  for (const auto& s : e.setup) {
    if (s == "good_results") {
      ASSERT_FALSE(good_results().empty()) << "could not make a valid results file";
      fs::copy_file(good_results(), tmp / "good.h5");
    } else if (s.rfind("damaged:", 0) == 0) {
      // a copy of the valid results file with one dataset damaged by
      // tests/python/damage_results.py (h5py alone; the kinds are listed there)
      ASSERT_FALSE(good_results().empty()) << "could not make a valid results file";
      const std::string cmd = std::string(PB_PYTHON) + " " + PB_SOURCE_DIR +
                              "/tests/python/damage_results.py " + good_results().string() + " " +
                              (tmp / "damaged.h5").string() + " " + s.substr(8) + " 2>&1";
      ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    } else if (s == "good_case") {
      fs::copy_file(fs::path(PB_CASES_DIR) / "falling_ball.toml", tmp / "case.toml");
    } else if (s == "big_file") {
      // sparse: 100 MB of size, next to nothing on disk
      std::ofstream(tmp / "big.toml").put('#');
      fs::resize_file(tmp / "big.toml", 100u << 20);
    } else if (s == "readonly_dir") {
      if (::geteuid() == 0) GTEST_SKIP() << "root writes into a folder of mode 0555";
      fs::create_directories(tmp / "readonly");
      fs::permissions(tmp / "readonly", fs::perms::owner_read | fs::perms::owner_exec |
                                            fs::perms::group_read | fs::perms::group_exec |
                                            fs::perms::others_read | fs::perms::others_exec);
    } else if (s == "fifo") {
      // a FIFO, a symbolic link to it, and a link to nothing: outputs that a
      // rename would replace with a regular file (issue 15)
      ASSERT_EQ(::mkfifo((tmp / "fifo").c_str(), 0600), 0) << std::strerror(errno);
      fs::create_symlink(tmp / "fifo", tmp / "fifolink");
      fs::create_symlink(tmp / "no_such_file.h5", tmp / "dangling");
      fs::create_directories(tmp / "report");
      ASSERT_EQ(::mkfifo((tmp / "report" / "report.html").c_str(), 0600), 0);
    } else {
      FAIL() << "unknown setup '" << s << "'";
    }
  }
  std::vector<std::string> args;
  for (std::string a : e.args) {
    for (const auto& [k, v] : vars) a = replace_all(a, k, v);
    args.push_back(a);
  }
  const auto before = listing(tmp);
  // the output options' files, unless they name something that is already there
  std::vector<fs::path> outputs;
  for (std::size_t i = 0; i + 1 < args.size(); ++i) {
    const bool is_output = args[i] == "--out" || args[i] == "--junit" || args[i] == "--summary";
    if (is_output && !fs::exists(args[i + 1])) outputs.emplace_back(args[i + 1]);
  }

  const Outcome o = run_planarbench(args, tmp, e.name);

  // no crash, no hang, no sanitizer report, the exit code of bad input
  EXPECT_FALSE(o.timed_out) << "no answer within 120 s";
  EXPECT_FALSE(o.signalled) << "killed by signal " << o.signal << "\n" << o.err;
  EXPECT_EQ(o.exit_code, e.exit_code) << o.err;
  EXPECT_EQ(o.err.find("Sanitizer"), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find("runtime error:"), std::string::npos) << o.err;

  // one line on stderr, nothing on stdout
  EXPECT_EQ(o.out, "") << "stdout must be empty";
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "not one line:\n" << o.err;
  EXPECT_TRUE(!o.err.empty() && o.err.back() == '\n') << o.err;
  EXPECT_EQ(o.err.rfind(kPrefix, 0), 0u) << o.err;
  for (const auto& want : e.expect) {
    EXPECT_NE(o.err.find(want), std::string::npos) << "lacks '" << want << "':\n" << o.err;
  }

  // nothing written: no output file, no temporary file, nothing else new
  for (const auto& p : outputs) EXPECT_FALSE(fs::exists(p)) << p << " was written";
  EXPECT_EQ(listing(tmp), before) << "files were made or changed in " << tmp;

  // the folder of a passing entry is not needed any more
  if (!HasFailure()) {
    std::error_code ec;
    fs::permissions(tmp / "readonly", fs::perms::owner_all, ec);
    fs::remove_all(tmp, ec);
  }
}

// entries by name; a name gtest cannot take still registers, and the corpus
// test below names the problem
std::string entry_test_name(const ::testing::TestParamInfo<Entry>& info) {
  const std::string& n = info.param.name;
  const auto& all = corpus().entries;
  const auto first = std::find_if(all.begin(), all.end(), [&](const Entry& x) { return x.name == n; });
  const bool unique = first != all.end() && static_cast<std::size_t>(first - all.begin()) == info.index;
  return valid_name(n) && unique ? n : "entry_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(corpus().entries), entry_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(BadInput);

// ---- the corpus itself ------------------------------------------------------------

// At least 30 distinct bad inputs (issue 7), each well formed.
TEST(Corpus, HoldsAtLeastThirtyDistinctWellFormedEntries) {
  const Corpus& c = corpus();
  ASSERT_EQ(c.error, "");
  EXPECT_GE(c.entries.size(), 30u);
  std::set<std::string> names;
  std::set<std::vector<std::string>> inputs;
  for (const auto& e : c.entries) {
    EXPECT_TRUE(valid_name(e.name)) << "name '" << e.name << "' is not [A-Za-z0-9_]+";
    EXPECT_TRUE(names.insert(e.name).second) << "name '" << e.name << "' is used twice";
    // the input is the command line and what the setup makes ({damaged} is
    // a different file for each damage)
    std::vector<std::string> input = e.args;
    input.insert(input.end(), e.setup.begin(), e.setup.end());
    EXPECT_TRUE(inputs.insert(input).second) << e.name << ": the same input as another entry";
    EXPECT_FALSE(e.what.empty()) << e.name << ": say what is wrong in `what`";
    EXPECT_FALSE(e.args.empty()) << e.name;
    EXPECT_EQ(e.exit_code, 2) << e.name << ": every corpus entry is bad input (exit 2)";
    EXPECT_FALSE(e.expect.empty()) << e.name << ": no expected substrings";
  }
}

// Every bad file of the corpus folders is used by some entry.
TEST(Corpus, UsesEveryBadFile) {
  std::string all_args;
  for (const auto& e : corpus().entries) {
    for (const auto& a : e.args) all_args += a + "\n";
  }
  for (const char* sub : {"case", "thresholds", "results"}) {
    for (const auto& f : fs::directory_iterator(kDataDir / sub)) {
      const std::string ref = "{data}/" + std::string(sub) + "/" + f.path().filename().string();
      EXPECT_NE(all_args.find(ref + "\n"), std::string::npos) << ref << " is in no entry";
    }
  }
}

}  // namespace
