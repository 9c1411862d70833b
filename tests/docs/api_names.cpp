// SPDX-License-Identifier: BSL-1.0
// Checks that docs/api.md names only what the headers declare:
//   seawire_api_names <source dir> <out.cpp>
// The code of the page is its fenced blocks (up to a `//` comment on each line) and its
// `backtick` spans. In that code:
//  - a header or page it names (nmea/stream.hpp, docs/enums.md) must exist;
//  - every identifier (a type, function, member function, enum value, option...) must appear in
//    the code of a header under include/seawire (comments and string literals left out), unless
//    it is C++ or the standard library's, or one of the page's placeholders listed below;
//  - every name qualified by a seawire namespace (nmea::decode, seawire::result,
//    robotx::light_pattern) is written to <out.cpp> as a using-declaration, which the test then
//    compiles: a name in the wrong namespace fails there.
// Exits 1, naming each line and identifier, when the page names something that does not exist.

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// C++ itself, the standard library and {fmt} names the page writes.
const std::set<std::string> language = {
    "auto",     "bool",     "char",        "class",        "concept",      "const",    "constexpr",
    "define",   "double",   "enum",        "explicit",     "false",        "float",    "if",
    "include",  "int",      "namespace",   "noexcept",     "nullopt",      "optional", "size_t",
    "span",     "std",      "string_view", "struct",       "template",     "true",     "typename",
    "u32",      "uint16_t", "uint32_t",    "uint8_t",      "using",        "variant",  "void",
    "array",    "chrono",   "sys_time",    "steady_clock", "system_clock", "now",      "time_point",
    "to_chars", "format",   "fmt",         "size",         "string",       "value",
};

// The page's placeholders: parameters, template parameters and example values that stand for
// what the caller writes (a header need not spell them).
const std::set<std::string> placeholders = {
    "A",
    "E",
    "M",
    "N",
    "P",
    "R",
    "T",
    "C",
    "Bits",
    "Signed",
    "Sets",
    "Set",
    "Slots",
    "Pgns",
    "Capacity",
    "sv",
    "v",
    "e",
    "f",
    "r",
    "s",
    "p",
    "n",
    "m",
    "b",
    "c",
    "hb",
    "a",
    "on",
    "off",
    "other",
    "member",
    "msg",
    "line",
    "sink",
    "chunk",
    "digits",
    "computed",
    "name",
    "opts",
    "part",
    "explain",
    "lookup",
    "type",
    "row",
    "why",
    "record",
    "payload",
    "header",
    "frame",
    "id",
    "first",
    "last",
    "places",
    "ticket",
    "status",
    "text",
    "reason",
    "message",
    "code",
    "code_or_address",
    "state",
    "allowed",
    "t",
    "between_dollar_and_star",
    "time_of_day_t",
    "all_ok",
    "MaxClients",
    "OutboxCapacity",
    "EventCapacity",
    "FrameRecognizer",
    "dec",
    "x",
    "y",
    "NAME",
    "in",
    "out",
    "policy",
    "sequence",
    "pgn",
    "source",
    "destination",
    "priority",
    "mantissa",
    "exponent",
    "format",
    "fn",
    "why",
};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The code of a header: comments and string and character literals blanked.
std::string code_of(const std::string& text) {
  std::string out = text;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out.compare(i, 2, "//") == 0) {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out.compare(i, 2, "/*") == 0) {
      const std::size_t end = out.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
      for (; i < stop; ++i)
        if (out[i] != '\n') out[i] = ' ';
    } else if (out[i] == '"' || out[i] == '\'') {
      // A digit separator (1'000) is not a character literal.
      if (out[i] == '\'' && i > 0 && std::isxdigit(static_cast<unsigned char>(out[i - 1])))
        continue;
      const char quote = out[i];
      out[i++] = ' ';
      while (i < out.size() && out[i] != quote && out[i] != '\n') {
        if (out[i] == '\\' && i + 1 < out.size()) out[i++] = ' ';
        out[i++] = ' ';
      }
      if (i < out.size() && out[i] == quote) out[i] = ' ';
    }
  }
  return out;
}

struct token {
  std::string qualifier;  // the names before `::`, if any ("anello::frame_table")
  std::string name;
  bool code_like;  // qualified, a member (.name), called (name(...)) or snake_case
};

// Identifiers of a line of the page's code; numbers (0xAB00, 4.50_dec) are skipped whole.
std::vector<token> tokens_of(const std::string& code) {
  std::vector<token> out;
  std::string previous;  // the identifier just before a `::`
  for (std::size_t i = 0; i < code.size();) {
    if (std::isdigit(static_cast<unsigned char>(code[i]))) {
      while (i < code.size() && (ident_char(code[i]) || code[i] == '.')) ++i;
      previous.clear();
    } else if (ident_start(code[i])) {
      const std::size_t start = i;
      while (i < code.size() && ident_char(code[i])) ++i;
      std::string name = code.substr(start, i - start);
      const bool code_like = !previous.empty() || (start > 0 && code[start - 1] == '.') ||
                             (i < code.size() && code[i] == '(') ||
                             name.find('_') != std::string::npos;
      out.push_back({previous, name, code_like});
      // A chain (anello::frame_table::field) keeps every namespace before the name.
      previous = code.compare(i, 2, "::") != 0 ? std::string()
                 : previous.empty()            ? name
                                               : previous + "::" + name;
      if (!previous.empty()) i += 2;
    } else if (code.compare(i, 2, "::") == 0 && !out.empty()) {
      i += 2;  // `Type<...>::member`: the qualifier was a template's name, not checked
    } else {
      if (code[i] != ' ' && code[i] != '<' && code[i] != '>') previous.clear();
      ++i;
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: seawire_api_names <source dir> <out.cpp>\n");
    return 2;
  }
  const fs::path source = argv[1];
  const fs::path include = source / "include";

  // Every identifier in the headers' code, and every namespace they open.
  std::set<std::string> declared;
  std::set<std::string> namespaces;
  std::vector<std::string> headers;
  for (const auto& entry : fs::recursive_directory_iterator(include / "seawire")) {
    if (entry.path().extension() != ".hpp") continue;
    const std::string relative = fs::relative(entry.path(), include).generic_string();
    // fmt.hpp needs {fmt}; impl/src.hpp defines, for SEAWIRE_SEPARATE_COMPILATION only.
    if (relative != "seawire/fmt.hpp" && relative != "seawire/impl/src.hpp")
      headers.push_back(relative);
    std::ifstream in(entry.path());
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string code = code_of(buffer.str());
    const auto found = tokens_of(code);
    for (std::size_t k = 0; k < found.size(); ++k) {
      declared.insert(found[k].name);
      if (found[k].name == "namespace" && k + 1 < found.size()) {
        for (std::size_t j = k + 1; j < found.size(); ++j) {
          namespaces.insert(found[j].name);
          if (j + 1 >= found.size() || found[j + 1].qualifier != found[j].name) break;
        }
      }
    }
  }

  std::ifstream page(source / "docs" / "api.md");
  if (!page) {
    std::fprintf(stderr, "seawire_api_names: cannot read docs/api.md\n");
    return 2;
  }
  int errors = 0;
  std::set<std::string> usings;
  std::string line;
  int number = 0;
  bool fenced = false;
  while (std::getline(page, line)) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      continue;
    }
    std::string code;
    std::string comment;  // prose, where only what looks like code is checked
    if (fenced) {
      const std::size_t slashes = line.find("//");
      code = line.substr(0, slashes);
      if (slashes != std::string::npos) comment = line.substr(slashes + 2);
    } else {
      for (std::size_t open = line.find('`'); open != std::string::npos;) {
        const std::size_t close = line.find('`', open + 1);
        if (close == std::string::npos) break;
        code += line.substr(open + 1, close - open - 1) + " ; ";
        open = line.find('`', close + 1);
      }
    }
    // Files the page names must exist; then they are not identifiers.
    const auto check_files = [&](std::string& text) {
      for (const char* extension : {".hpp", ".md"}) {
        for (std::size_t at = text.find(extension); at != std::string::npos;
             at = text.find(extension, at + 1)) {
          std::size_t start = at;
          while (start > 0 &&
                 (ident_char(text[start - 1]) || text[start - 1] == '/' || text[start - 1] == '-'))
            --start;
          const std::string file = text.substr(start, at - start) + extension;
          const bool exists =
              file.rfind("docs/", 0) == 0 ? fs::exists(source / file)
              : file.rfind("seawire/", 0) == 0
                  ? fs::exists(include / file)
                  : file.find('*') == std::string::npos && fs::exists(include / "seawire" / file);
          const bool pattern = text.compare(start - (start > 0 ? 1 : 0), 1, "*") == 0;
          if (!exists && !pattern) {
            std::fprintf(stderr, "docs/api.md:%d: no file %s\n", number, file.c_str());
            ++errors;
          }
          text.replace(start, at + std::string(extension).size() - start,
                       at + std::string(extension).size() - start, ' ');
        }
      }
    };
    check_files(code);
    check_files(comment);
    std::vector<token> found = tokens_of(code_of(code));
    for (const token& t : tokens_of(code_of(comment)))
      if (t.code_like) found.push_back(t);
    for (const token& t : found) {
      const std::string outer = t.qualifier.substr(0, t.qualifier.find("::"));
      const std::string inner = t.qualifier.substr(
          t.qualifier.rfind("::") == std::string::npos ? 0 : t.qualifier.rfind("::") + 2);
      if (outer == "std" || outer == "chrono" || outer == "fmt") continue;
      if (!declared.count(t.name) && !language.count(t.name) && !placeholders.count(t.name)) {
        std::fprintf(stderr, "docs/api.md:%d: `%s` is declared by no header\n", number,
                     t.name.c_str());
        ++errors;
      }
      if (namespaces.count(inner)) usings.insert(t.qualifier + "::" + t.name);
    }
  }

  std::ofstream out(argv[2]);
  out << "// Generated by tests/docs/api_names.cpp from docs/api.md: do not edit.\n";
  for (const std::string& h : headers) out << "#include \"" << h << "\"\n";
  // One namespace each: kingfisher::from_vehicle and sandshark::from_vehicle may not meet.
  int n = 0;
  for (const std::string& u : usings) {
    const std::string name = u.substr(u.rfind("::") + 2);
    const std::string full = u.rfind("seawire::", 0) == 0 ? "::" + u : "::seawire::" + u;
    out << "namespace api_name_" << ++n << " {\n";
    if (namespaces.count(name))
      out << "namespace checked = " << full << ";\n";
    else
      out << "using " << full << ";\n";
    out << "}\n";
  }
  if (!out) {
    std::fprintf(stderr, "seawire_api_names: cannot write %s\n", argv[2]);
    return 2;
  }
  std::printf("seawire_api_names: %zu qualified names to compile\n", usings.size());
  return errors == 0 ? 0 : 1;
}
