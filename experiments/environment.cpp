#include "environment.hpp"

#include <ccdlab_git_hash.hpp>

#include <fstream>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <unistd.h>

namespace ccdlab {

nlohmann::json environment_json(int threads) {
  std::string cpu = "unknown";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);) {
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  return {{"ccdlab_version", CCDLAB_VERSION},
          {"git", CCDLAB_GIT_HASH},
          {"compiler", CCDLAB_COMPILER},
          {"flags", CCDLAB_CXX_FLAGS},
          {"cpu", cpu},
          {"cores", std::thread::hardware_concurrency()},
          {"threads", threads},
          {"hostname", host}};
}

long long peak_memory_bytes() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<long long>(u.ru_maxrss) * 1024;
}

}  // namespace ccdlab
