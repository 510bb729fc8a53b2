// Replays fuzz inputs through the same checks that the libFuzzer targets run,
// without libFuzzer: an ordinary g++ build, so that ctest needs no clang.
//
//   contact-fuzz-replay [--stats] TARGET PATH...
//
// Each PATH is a file or a directory whose regular files (not starting with
// '.', and not README*) are replayed in name order. A path that does not exist
// is an error. Every failing check prints its report, naming the file; the
// exit status is then 1.
// --stats prints, at the end, the worst error per algorithm and type.
#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "checks.hpp"

namespace {

std::vector<std::string> files_under(const std::string& path, bool& ok) {
  std::vector<std::string> files;
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) {
    std::fprintf(stderr, "contact-fuzz-replay: %s does not exist\n", path.c_str());
    ok = false;
    return files;
  }
  if (!S_ISDIR(info.st_mode)) {
    files.push_back(path);
    return files;
  }
  if (DIR* dir = opendir(path.c_str())) {
    while (const dirent* entry = readdir(dir)) {
      const std::string name = entry->d_name;
      if (name.empty() || name[0] == '.' || name.rfind("README", 0) == 0) continue;
      const std::string full = path + "/" + name;
      struct stat file_info {};
      if (stat(full.c_str(), &file_info) == 0 && S_ISREG(file_info.st_mode)) files.push_back(full);
    }
    closedir(dir);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  bool print_stats = false;
  int first = 1;
  if (first < argc && std::string(argv[first]) == "--stats") {
    print_stats = true;
    ++first;
  }
  if (argc - first < 2) {
    std::fprintf(stderr, "usage: %s [--stats] TARGET PATH...\n  targets:", argv[0]);
    for (const char* name : contact::fuzz::target_names) std::fprintf(stderr, " %s", name);
    std::fprintf(stderr, "\n");
    return 2;
  }
  const std::string target = argv[first];
  bool ok = true;
  std::vector<std::string> files;
  for (int i = first + 1; i < argc; ++i) {
    auto more = files_under(argv[i], ok);
    std::printf("%s: %zu files\n", argv[i], more.size());
    files.insert(files.end(), more.begin(), more.end());
  }
  if (!ok) return 2;
  const auto& bounds = contact::fuzz::claimed();
  std::printf("claimed bounds (from %s):", contact::fuzz::bound_source().c_str());
  for (const auto& [branch, ulps] : bounds.per_branch()) std::printf(" %s %g,", branch.c_str(), ulps);
  std::printf(" largest %g ulps\n", bounds.largest());
  std::fflush(stdout);
  contact::fuzz::throw_on_finding() = true;
  std::vector<std::string> failing;
  for (const std::string& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    contact::fuzz::current_input_name() = file.c_str();
    try {
      if (!contact::fuzz::run_check(target, bytes.data(), bytes.size())) {
        std::fprintf(stderr, "contact-fuzz-replay: unknown target %s\n", target.c_str());
        return 2;
      }
    } catch (const contact::fuzz::finding&) {
      failing.push_back(file);
    }
  }
  contact::fuzz::current_input_name() = nullptr;
  std::fflush(stderr);
  if (print_stats) contact::fuzz::stats().print(stdout);
  if (!failing.empty()) {
    std::printf("replayed %zu inputs through '%s': %zu FAILED\n", files.size(), target.c_str(), failing.size());
    for (const auto& file : failing) std::printf("  failed: %s\n", file.c_str());
    return 1;
  }
  std::printf("replayed %zu inputs through '%s': no finding\n", files.size(), target.c_str());
  return 0;
}
