// Tiny command-line reader shared by the subcommands: `--key value` pairs, repeatable keys.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

class ArgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Args {
 public:
  // `flags` are options without a value (e.g. "--help").
  Args(int argc, char** argv, int first, const std::vector<std::string>& known,
       const std::vector<std::string>& flags = {});
  bool has(const std::string& key) const;
  std::string get(const std::string& key, const std::string& fallback = "") const;
  std::vector<std::string> all(const std::string& key) const;
  int getInt(const std::string& key, int fallback) const;
  // "1280x720" -> w, h; throws ArgError for anything else.
  void getSize(const std::string& key, int& w, int& h) const;

 private:
  std::vector<std::pair<std::string, std::string>> values_;
};

// Writes RGBA8 rows (bottom-up, as GL reads them) as a PNG; throws std::runtime_error on failure.
void writePng(const std::string& path, int width, int height, const std::vector<unsigned char>& rgbaBottomUp);

}  // namespace sl
