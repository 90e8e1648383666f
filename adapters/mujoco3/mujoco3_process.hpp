// The Node process that runs MuJoCo 3.3.8's WebAssembly build for engine
// "mujoco3" (wasm/server.mjs): where Node and the pinned package are, starting
// it, and its framed messages over two pipes. A crash of the WebAssembly side
// (the process ends) or a hang (no answer within the time limit) becomes an
// EngineError with what the process wrote to stderr: the run ends, the command
// goes on (the same isolation as every engine: run_isolation.hpp).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace pb::internal::mujoco3 {

// Where the WebAssembly side lives, and whether it can run here.
struct Mujoco3Install {
  std::string node;        // the Node executable ("" when none)
  std::string server;      // wasm/server.mjs
  std::string package_dir; // wasm/ (node_modules/mujoco-js inside)
  bool available = false;
  std::string reason;      // one line when not available, with the command that installs it
};

// PB_NODE (else `node` on PATH) and PB_MUJOCO3_DIR (else the source tree's
// adapters/mujoco3/wasm, fixed at configure time); checks that the package
// mujoco-js is installed there.
[[nodiscard]] const Mujoco3Install& mujoco3_install();

// s, the longest the WebAssembly side may take to answer one message before a
// run is ended as a hang: PB_MUJOCO3_TIMEOUT_S, else `unset_s` (120 for a
// run: loading the module and a model takes well under a second here, a step
// a few us). Not a setting: it changes no number a run computes. Throws
// EngineError when the variable is not a number in [0.1, 86400].
[[nodiscard]] double mujoco3_answer_timeout_s(double unset_s = 120.0);

// message kinds (wasm/server.mjs)
enum class Kind : std::uint32_t {
  version = 0, load = 1, start = 2, solrefs = 3, run = 4, quit = 5, stats = 6,
  info = 1, batch = 2, error = 9,
};

// what an INFO answer's field must hold
enum class JsonField { string, integer, number };

class Mujoco3Process {
 public:
  // starts `node server.mjs`; throws EngineError when it cannot
  explicit Mujoco3Process(const Mujoco3Install& install, double answer_timeout_s);
  ~Mujoco3Process();
  Mujoco3Process(const Mujoco3Process&) = delete;
  Mujoco3Process& operator=(const Mujoco3Process&) = delete;

  void send(Kind kind, const void* data, std::size_t bytes);
  void send_numbers(Kind kind, const std::vector<double>& values) {
    send(kind, values.data(), values.size() * sizeof(double));
  }
  // the next frame; it must be of kind `expected` (an ERROR frame throws its
  // text as EngineError); `bytes` receives the payload
  void receive(Kind expected, std::vector<unsigned char>& bytes);
  void receive_numbers(Kind expected, std::vector<double>& values);
  // the next frame, an INFO answer to `answer_to` (a command's name): a JSON
  // object holding `fields` of those types, else the process's fault (one
  // line naming the field, never a parser's exception)
  [[nodiscard]] nlohmann::json receive_info(
      const char* answer_to, std::initializer_list<std::pair<const char*, JsonField>> fields);
  // the last lines the process wrote to stderr (MuJoCo's warnings), "" if none
  [[nodiscard]] std::string stderr_tail() const;

 private:
  [[noreturn]] void fail(const std::string& what);
  void read_exactly(unsigned char* out, std::size_t n);

  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  int stderr_file_ = -1;
  double timeout_s_ = 60.0;
  std::vector<unsigned char> scratch_;
};

}  // namespace pb::internal::mujoco3
