#pragma once
// The one error type for bad input. Its message is a single line that names the file,
// the field (a JSON path such as `bodies[3].radius`) and what is wrong, so the CLI can
// print it as is and exit with status 2.
#include <stdexcept>
#include <string>

namespace ccd {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& what)
      : std::runtime_error(file + ": " + (field.empty() ? std::string() : field + ": ") + what),
        file_(file), field_(field) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  std::string field_;
};

}  // namespace ccd
