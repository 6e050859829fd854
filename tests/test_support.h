#pragma once
// Helpers shared by the core, io and cli tests: relative comparison, data paths, running a binary.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cam::test {

/// True in a build with AddressSanitizer (the debug preset): code runs several times slower and
/// cannot run under an address-space limit, which timing bounds and memory tests must allow for.
/// GCC says so with __SANITIZE_ADDRESS__, clang only through __has_feature.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAMWRIGHT_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(CAMWRIGHT_TEST_ASAN)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

/// |actual - expected| <= rel·max(|expected|, floor): relative, with an absolute floor for zeros.
inline ::testing::AssertionResult relClose(double actual, double expected, double rel,
                                           double floor = 0.0) {
    const double tol = rel * std::max(std::abs(expected), floor);
    if (std::abs(actual - expected) <= tol) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "actual " << actual << " vs expected " << expected << ": difference "
           << std::abs(actual - expected) << " > tolerance " << tol;
}

inline std::string dataPath(const std::string& relative) {
    return std::string(CAMWRIGHT_TEST_DATA) + "/" + relative;
}
inline std::string examplePath(const std::string& name) {
    return std::string(CAMWRIGHT_EXAMPLES) + "/" + name;
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct RunResult {
    int exitCode = -1;  ///< -1 if killed by a signal
    int signal = 0;
    std::string out;
    std::string err;
};

/// Runs a program with arguments (no shell), capturing stdout and stderr; kills it after
/// `timeoutS` seconds so a hang fails the test instead of blocking the suite. Under the
/// sanitizers a search that takes 5 s in release takes 50–65 s (`size --best-pivot`), so the
/// guard waits longer there.
inline RunResult run(const std::string& program, const std::vector<std::string>& args,
                     int timeoutS = kSanitized ? 250 : 60) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path();
    const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(std::rand());
    const std::string outPath = (dir / ("cw_out_" + tag)).string();
    const std::string errPath = (dir / ("cw_err_" + tag)).string();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int o = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        const int e = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        ::dup2(o, 1);
        ::dup2(e, 2);
        ::alarm(static_cast<unsigned>(timeoutS));
        std::vector<char*> argv{const_cast<char*>(program.c_str())};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    RunResult r;
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    r.out = readFile(outPath);
    r.err = readFile(errPath);
    fs::remove(outPath);
    fs::remove(errPath);
    return r;
}

/// A fresh folder under the system temp folder, removed with everything in it at the end.
class TempDir {
public:
    TempDir() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "camwright_test_XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) ADD_FAILURE() << "mkdtemp failed";
        m_path = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return m_path; }
    [[nodiscard]] std::string file(const std::string& name) const {
        return (m_path / name).string();
    }

private:
    std::filesystem::path m_path;
};

/// The permission bits (07777) of a file, following symlinks; -1 if it cannot be examined.
inline int fileMode(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 ? static_cast<int>(st.st_mode & 07777) : -1;
}

/// Writes a file with exactly `mode` (not masked by the umask).
inline void writeFileWithMode(const std::string& path, const std::string& content, int mode) {
    std::ofstream(path, std::ios::binary) << content;
    ::chmod(path.c_str(), static_cast<mode_t>(mode));
}

/// The names in a folder (hidden ones too), sorted.
inline std::vector<std::string> folderEntries(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(folder))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// Knuth's MMIX linear congruential generator: the same numbers on every platform.
class Lcg {
public:
    explicit Lcg(std::uint64_t seed) : m_state(seed * 2654435761ULL + 1ULL) {}
    double uniform() {
        m_state = m_state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(m_state >> 11) * (1.0 / 9007199254740992.0);
    }
    double range(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    std::uint64_t m_state;
};

/// Writes `text` to the file `name` in the system temp folder and returns its path.
inline std::string writeTempFile(const std::string& name, const std::string& text) {
    const std::filesystem::path p = std::filesystem::temp_directory_path() / name;
    std::ofstream(p) << text;
    return p.string();
}

/// The same, in a file of the running test's own ("PREFIX_Suite_Test_NAME"): ctest runs a
/// file's tests side by side, and one rewriting a file that another's program is reading
/// hands that one a truncated file.
inline std::string writeTestTempFile(const std::string& prefix, const std::string& name,
                                     const std::string& text) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string unique = prefix + "_" + info->test_suite_name() + "_" + info->name() + "_" + name;
    for (char& c : unique) {
        if (c == '/') c = '-';  // parameterised tests: "Cams/ExportEveryCam"
    }
    return writeTempFile(unique, text);
}

/// Writes `text` to `path` byte for byte.
inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The bundled six-lobe arc cam, the example most tests start from.
inline const std::string kExample = examplePath("six-lobe-arc-cam.cam.json");

/// LinuxCNC's G-code interpreter as the project runs it (tests/tools/rs274: Debian's package,
/// unpacked on first use; packaging/install-deps.sh unpacks it beforehand). It serialises its
/// runs itself.
inline const std::string kRs274 = std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/tools/rs274";

inline RunResult runCli(const std::vector<std::string>& args) { return run(CAMWRIGHT_CLI, args); }

}  // namespace cam::test
