// libFuzzer harness: the manifest.json reader of a generated suite (the degenerate-case suite's
// format, written by `exactccd generate`), through the command that reads it, `exactccd study`
// (run_study), on a scratch suite whose manifest is the input. The suite holds one small family
// folder, "vf_t0" (the first two queries of tests/data/degenerate-suite/vf_t0 and their TOI
// sidecar), so that manifests naming it are studied to the end.
//
// Properties: the command returns or throws exactccd::InputError or oracle::UsageError, nothing
// else (a nlohmann::json exception or a crash is a defect: a bad manifest must give a clear
// message); when it returns, the status is kExitAgree, since the verdicts and TOIs come from
// the family's files, which are right, whatever the manifest says about them.
#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "study/study.hpp"
#include "exactccd/query_file.hpp"
#include "fuzz_support.hpp"
#include "oracle/common.hpp"

using namespace exactccd;

namespace {

// The first two members of vf_t0 (a contact at t = 0, then a near miss) and their sidecar.
constexpr char kData[] =
    "37,64,-31,32,-9,16,1\n11,16,-11,8,-9,16,1\n1,16,-1,4,-9,16,1\n17,16,-3,8,-9,16,1\n"
    "77,64,-7,32,5,16,1\n11,16,-3,8,-9,16,1\n1,16,3,4,-9,16,1\n17,16,5,8,-9,16,1\n"
    "37,64,-31,32,-5066549580791807,9007199254740992,0\n11,16,-11,8,-9,16,0\n"
    "1,16,-1,4,-9,16,0\n17,16,-3,8,-9,16,0\n77,64,-7,32,5,16,0\n11,16,-3,8,-9,16,0\n"
    "1,16,3,4,-9,16,0\n17,16,5,8,-9,16,0\n";
constexpr char kToi[] = "0,1,0,0\n1,0,,\n";

void write_text(const std::filesystem::path& path, const char* text) {
  fuzz::write_file(path, reinterpret_cast<const std::uint8_t*>(text),
                   std::char_traits<char>::length(text));
}

const std::filesystem::path& suite() {
  static const std::filesystem::path folder = [] {
    const std::filesystem::path s = fuzz::scratch_folder() / "suite";
    const std::filesystem::path family = s / "vf_t0" / "vertex-face";
    std::filesystem::create_directories(family);
    write_text(family / "data_0.csv", kData);
    write_text(family / "toi_0.csv", kToi);
    // The study's tables go to stdout: not wanted in the fuzzer's log (it reports on stderr).
    const int null = open("/dev/null", O_WRONLY);
    if (null < 0 || dup2(null, STDOUT_FILENO) < 0) fuzz::fail("cannot redirect stdout");
    close(null);
    return s;
  }();
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::write_file(suite() / "manifest.json", data, size);
  study::StudyOptions options;
  options.paths = {suite().string()};
  options.repetitions = 1;
  options.widths = {0.0};
  options.tolerances = {1e-9};
  options.json = (size & 1) != 0;  // both report writers, chosen by a bit of the input
  int status = -1;
  try {
    status = study::run_study(options);
  } catch (const InputError&) {
    return 0;
  } catch (const oracle::UsageError&) {
    return 0;
  }
  fuzz::require(status == oracle::kExitAgree,
                "study exit status " + std::to_string(status) + " on correct family files");
  return 0;
}
