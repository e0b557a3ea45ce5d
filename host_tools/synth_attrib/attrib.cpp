// htx-synth-attrib's attribution: where a flattened iCE40 netlist's area goes. Counting per
// module needs an unflattened synthesis, which cannot trim a module to what each instance uses and
// so misleads (docs/area.md); this reads Yosys's JSON netlist of the flattened design instead.
// Every flip-flop belongs to the scope of its register (the hierarchical name without its last
// part); every SB_LUT4 and SB_CARRY to the scope of the first named signal found by following its
// output forward (LUTs that ABC made out of several signals name none themselves; a mapped name
// that steps forward through a cell does not count as a name, see wanders()). A signal named in
// several scopes counts where it is made (see better()). Scopes are cut to --depth parts below
// the common prefix and summed. The split is a heuristic; the total is exact.
#include "attrib.hpp"

#include <algorithm>
#include <map>
#include <regex>
#include <unordered_map>
#include <vector>

namespace htx::synth {

namespace {

// A net name without what Yosys appends after a "$" ("$func$FILE:LINE...", whose file name
// holds dots).
std::string base_name(const std::string& name) { return name.substr(0, name.find('$')); }

// Where the cells' ports start in a base name (npos: none). Yosys's iCE40 mapping names the nets
// between cells after a signal they lead to, with the cells' ports appended ("x_q_SB_LUT4_I0_O").
size_t mapped_at(const std::string& s) {
  const size_t dot = s.rfind('.');
  return s.find("_SB_", dot == std::string::npos ? 0 : dot);
}

// The signal a net is named after.
std::string signal_of(const std::string& name) {
  const std::string s = base_name(name);
  const size_t mapped = mapped_at(s);
  return mapped == std::string::npos ? s : s.substr(0, mapped);
}

bool is_ff(const std::string& type) { return type.rfind("SB_DFF", 0) == 0; }

// Whether a mapped name is a path from its signal that steps forward through a cell (from an
// input port to the output: "x_SB_LUT4_I2_O" is the output of a LUT that x feeds). Such a path can
// wander through any logic x feeds and back, so it says nothing about where its net is made: a
// net named only so counts as unnamed. Backward steps ("x_SB_LUT4_O_I2", x's LUT's input I2) stay
// in the cone that makes x.
bool wanders(const std::string& name) {
  static const std::regex forward("_(I[0-3]|CI|D|E|R|S)(_[0-9]+)?_(O|CO|Q)(_[0-9]+)?(_|$)");
  const std::string s = base_name(name);
  const size_t mapped = mapped_at(s);
  return mapped != std::string::npos && std::regex_search(s.substr(mapped), forward);
}

// The scope of a net name: its base name without its last dotted part.
std::string scope_of(const std::string& name) {
  const std::string s = base_name(name);
  const size_t dot = s.rfind('.');
  return dot == std::string::npos ? std::string() : s.substr(0, dot);
}

std::string cut(const std::string& scope, size_t skip, int depth) {
  std::string s = scope.size() > skip ? scope.substr(skip) : std::string();
  size_t pos = 0;
  for (int i = 0; i < depth; ++i) {
    pos = s.find('.', pos);
    if (pos == std::string::npos) return s;
    ++pos;
  }
  return s.substr(0, pos - 1);
}

size_t depth_of(const std::string& name) {
  const std::string s = base_name(name);
  return static_cast<size_t>(std::count(s.begin(), s.end(), '.'));
}

// lowRISC port names: an input port ("_i") is the consumer's alias of a signal made elsewhere;
// an output port ("_o") is usually made in its module but may only pass a signal through.
bool is_port(const std::string& name, char dir) {
  const std::string s = base_name(name);
  return s.size() >= 2 && s[s.size() - 2] == '_' && s.back() == dir;
}

// Of two names of one bit, whether a is the better place to count it: not an input port; then
// the deepest (a bit has a name in every scope it passes through, and is made in the deepest);
// then not an output port (a pass-through's output and its source are equally deep); then the
// shorter.
bool better(const std::string& a, const std::string& b) {
  if (is_port(a, 'i') != is_port(b, 'i')) return !is_port(a, 'i');
  const size_t da = depth_of(a), db = depth_of(b);
  if (da != db) return da > db;
  if (is_port(a, 'o') != is_port(b, 'o')) return !is_port(a, 'o');
  return a.size() < b.size();
}

class Netlist {
 public:
  explicit Netlist(const Json& module) : module_(module) {
    for (const auto& [name, net] : module["netnames"].items()) {
      if (net.value("hide_name", 0) != 0 || wanders(name)) continue;
      for (const Json& bit : net["bits"]) {
        if (!bit.is_number_integer()) continue;
        auto [it, fresh] = name_of_bit_.emplace(bit.get<long>(), name);
        if (!fresh && better(name, it->second)) it->second = name;
      }
    }
    for (const auto& [cell, body] : module["cells"].items()) {
      const Json& dirs = body.value("port_directions", Json::object());
      for (const auto& [port, bits] : body["connections"].items()) {
        const bool out = dirs.value(port, std::string("input")) == "output";
        for (const Json& bit : bits) {
          if (!bit.is_number_integer()) continue;
          if (!out) sinks_[bit.get<long>()].push_back(cell);
        }
      }
    }
  }

  // The scope a cell's area belongs to ("" when no named signal is reachable).
  std::string owner(const std::string& cell) {
    auto memo = owner_.find(cell);
    if (memo != owner_.end()) return memo->second;
    owner_[cell] = "";  // breaks cycles through flip-flop-free loops
    const Json& body = module_["cells"][cell];
    const std::string type = body["type"];
    std::string result;
    const char* out_port = type == "SB_LUT4" ? "O" : type == "SB_CARRY" ? "CO" : nullptr;
    if (is_ff(type)) {
      // Yosys names a flip-flop after its register ("..._q_SB_DFFER_Q_3"), which is better than
      // any alias of the Q net; a generated name ("$auto$...") falls back to the net.
      const size_t cut_at = cell.find("_SB_DFF");
      result = (cell[0] != '$' && cut_at != std::string::npos) ? cell.substr(0, cut_at)
                                                                : named(body["connections"]["Q"][0]);
    } else if (out_port != nullptr) {
      const Json& bit = body["connections"][out_port][0];
      result = named(bit);
      if (result.empty() && bit.is_number_integer()) {
        auto s = sinks_.find(bit.get<long>());
        if (s != sinks_.end()) {
          for (const std::string& next : s->second) {
            result = owner(next);
            if (!result.empty()) break;
          }
        }
      }
    }
    owner_[cell] = result;
    return result;
  }

 private:
  std::string named(const Json& bit) const {
    if (!bit.is_number_integer()) return "";
    auto it = name_of_bit_.find(bit.get<long>());
    return it == name_of_bit_.end() ? "" : it->second;
  }

  const Json& module_;
  std::unordered_map<long, std::string> name_of_bit_;
  std::unordered_map<long, std::vector<std::string>> sinks_;
  std::unordered_map<std::string, std::string> owner_;
};

}  // namespace

std::string attribute(const Json& module, const std::string& top, int depth, bool by_signal) {
  Netlist net(module);

  // (scope, type); the top module's own signals have the scope "(top)", cells that reach no
  // named signal "(unnamed)".
  std::vector<std::pair<std::string, std::string>> cells;
  bool any_top = false;
  for (const auto& [cell, body] : module["cells"].items()) {
    const std::string type = body["type"];
    if (type == "SB_LUT4" || type == "SB_CARRY" || is_ff(type)) {
      const std::string name = net.owner(cell);
      // By signal, the signal's own name is its row (a top signal's name has no scope).
      std::string scope = name.empty() ? "(unnamed)" : by_signal ? signal_of(name) : scope_of(name);
      if (scope.empty()) {
        scope = "(top)";
        any_top = true;
      }
      cells.emplace_back(scope, type);
    }
  }
  // The common prefix of the named scopes, in whole parts ("a.b."), left out of the table; none
  // when the top module has cells of its own.
  std::string prefix;
  bool first = true;
  for (const auto& [scope, type] : cells) {
    if (any_top) break;
    if (scope == "(unnamed)") continue;
    const std::string dotted = scope + ".";
    if (first) {
      prefix = dotted;
      first = false;
    }
    size_t n = 0;
    while (n < prefix.size() && n < dotted.size() && prefix[n] == dotted[n]) ++n;
    const size_t dot = n == 0 ? std::string::npos : prefix.rfind('.', n - 1);  // last whole part
    prefix.resize(dot == std::string::npos ? 0 : dot + 1);
  }
  std::map<std::string, Counts> by_scope;
  Counts total;
  for (const auto& [scope, type] : cells) {
    std::string key = scope.front() == '(' ? scope
                      : by_signal         ? scope.substr(std::min(prefix.size(), scope.size()))
                                          : cut(scope, prefix.size(), depth);
    // (The common prefix's own scope, e.g. a harness's registers around the design it holds.)
    if (key.empty()) key = "(own)";
    Counts& row = by_scope[key];
    for (Counts* c : {&row, &total}) {
      ++(type == "SB_LUT4" ? c->lut4 : type == "SB_CARRY" ? c->carry : c->ff);
    }
  }
  std::vector<std::pair<std::string, Counts>> rows(by_scope.begin(), by_scope.end());
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return a.second.lut4 != b.second.lut4 ? a.second.lut4 > b.second.lut4 : a.first < b.first;
  });
  std::string table = std::string(by_signal ? "signal" : "scope") + " (below " +
                      (prefix.empty() ? top : prefix.substr(0, prefix.size() - 1)) +
                      ") | SB_LUT4 | SB_CARRY | flip-flops\n";
  for (const auto& [scope, c] : rows) {
    table += scope + " | " + std::to_string(c.lut4) + " | " + std::to_string(c.carry) + " | " +
             std::to_string(c.ff) + "\n";
  }
  table += "total | " + std::to_string(total.lut4) + " | " + std::to_string(total.carry) + " | " +
           std::to_string(total.ff) + "\n";
  return table;
}

}  // namespace htx::synth
