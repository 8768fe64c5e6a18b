#include "report/page_text.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace pivot::report {

std::string num(const char* spec, double v) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, spec, v);
    return buffer;
}

std::string machineName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

std::string todayUtc() {
    std::time_t now = std::time(nullptr);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%d", std::gmtime(&now));
    return buffer;
}

bool writeFile(const std::filesystem::path& path, const std::string& text, std::string& problem) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) problem = "cannot write " + path.string();
    return static_cast<bool>(out);
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace pivot::report
