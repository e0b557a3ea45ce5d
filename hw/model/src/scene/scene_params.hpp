// Parsing of scene specs `name:key=value,...` and typed, range-checked access to the values.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "htx/model/scenes.hpp"

namespace htx {

class SceneParams {
 public:
  // Splits `spec` into the scene name and its key=value pairs. Throws std::invalid_argument on
  // malformed pairs or repeated keys.
  explicit SceneParams(const std::string& spec);

  const std::string& name() const { return name_; }
  double number(const std::string& key, double fallback, double min, double max, const char* unit = "");
  int integer(const std::string& key, int fallback, int min, int max, const char* unit = "");
  // Every parameter asked for so far, in the order first asked.
  const std::vector<SceneParamInfo>& asked() const { return asked_; }
  // Throws when a given key was never asked for (a misspelt parameter must not pass silently).
  void check_all_used() const;

 private:
  std::string name_;
  std::map<std::string, std::string> values_;
  std::vector<SceneParamInfo> asked_;

  bool was_asked(const std::string& key) const;
  double read(const std::string& key, double fallback, double min, double max);
  void note(const std::string& key, double fallback, double min, double max, bool integer, const char* unit);
};

}  // namespace htx
