// A chart's SVG made fit to inline in a report (html_svg.hpp).
#include "html_svg.hpp"

#include <cctype>
#include <stdexcept>

namespace covopt::internal {
namespace {

bool StartsWith(std::string_view text, std::size_t at, std::string_view head) {
  return text.substr(at, head.size()) == head;
}

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string Lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

class Rewriter {
 public:
  Rewriter(std::string_view prefix, std::size_t number) : prefix_(prefix), number_(number) {}

  [[noreturn]] void Fail(const std::string& what) const {
    throw std::invalid_argument("report: chart " + std::to_string(number_) + ": " + what);
  }

  /// An attribute value: ids prefixed, local references rewritten, external ones refused.
  std::string Value(const std::string& name, std::string_view value) const {
    std::string out;
    if (name == "id") return std::string(prefix_) + std::string(value);
    if (name == "href" || name == "xlink:href") {
      if (value.empty()) return "";
      // A raster gnuplot embeds (pm3d maps drawn as an image): inline bytes, nothing fetched.
      if (value.starts_with("data:image/png;base64,")) return std::string(value);
      if (value.front() != '#') Fail("refers to an external resource (" + name + "=\"" + std::string(value) + "\")");
      out = "#";
      out += prefix_;
      out += value.substr(1);
      return out;
    }
    // url(#x) in presentation attributes and style="..."; url() of anything else is external.
    std::size_t at = 0;
    while (at < value.size()) {
      const std::size_t url = value.find("url(", at);
      if (url == std::string_view::npos) break;
      std::size_t inside = url + 4;
      while (inside < value.size() && (IsSpace(value[inside]) || value[inside] == '\'' || value[inside] == '"')) ++inside;
      if (inside >= value.size() || value[inside] != '#') Fail("refers to an external resource (url() in " + name + ")");
      out.append(value.substr(at, inside + 1 - at));
      out += prefix_;
      at = inside + 1;
    }
    out.append(value.substr(at));
    return out;
  }

  /// One start or end tag, `tag` from '<' to '>' inclusive.
  void Tag(std::string_view tag, std::string& out) const {
    std::size_t i = tag.size() > 1 && tag[1] == '/' ? 2 : 1;
    while (i < tag.size() && !IsSpace(tag[i]) && tag[i] != '>' && tag[i] != '/') ++i;
    out.append(tag.substr(0, i));  // "<name" or "</name"
    while (i < tag.size()) {
      const char c = tag[i];
      if (IsSpace(c) || c == '/' || c == '>') {
        out += c;
        ++i;
        continue;
      }
      const std::size_t name_begin = i;
      while (i < tag.size() && !IsSpace(tag[i]) && tag[i] != '=' && tag[i] != '>' && tag[i] != '/') ++i;
      const std::string name = Lower(tag.substr(name_begin, i - name_begin));
      std::size_t j = i;
      while (j < tag.size() && IsSpace(tag[j])) ++j;
      if (j >= tag.size() || tag[j] != '=') Fail("attribute '" + name + "' has no value (not well-formed XML)");
      ++j;
      while (j < tag.size() && IsSpace(tag[j])) ++j;
      if (j >= tag.size() || (tag[j] != '"' && tag[j] != '\'')) Fail("attribute '" + name + "' is not quoted");
      const char quote = tag[j];
      const std::size_t close = tag.find(quote, j + 1);
      if (close == std::string_view::npos) Fail("attribute '" + name + "' is not closed");
      const std::string_view value = tag.substr(j + 1, close - j - 1);
      i = close + 1;
      if (name.size() > 2 && name.compare(0, 2, "on") == 0) continue;  // an event handler: script
      out += ' ';
      out.append(tag.substr(name_begin, name.size()));
      out += '=';
      out += quote;
      out += Value(name, value);
      out += quote;
    }
  }

 private:
  std::string_view prefix_;
  std::size_t number_;
};

/// The position of the root's "<svg" (followed by a space, '>' or '/').
std::size_t RootStart(std::string_view svg) {
  std::size_t at = 0;
  while ((at = svg.find("<svg", at)) != std::string_view::npos) {
    const std::size_t after = at + 4;
    if (after < svg.size() && (IsSpace(svg[after]) || svg[after] == '>' || svg[after] == '/')) return at;
    at = after;
  }
  return std::string_view::npos;
}

}  // namespace

std::string InlineSvg(std::string_view svg, std::string_view prefix, std::size_t number) {
  const Rewriter rewriter(prefix, number);
  const std::size_t begin = RootStart(svg);
  const std::size_t end = svg.rfind("</svg>");
  if (begin == std::string_view::npos || end == std::string_view::npos || end < begin) {
    rewriter.Fail("no <svg> ... </svg> element");
  }
  const std::string_view body = svg.substr(begin, end + 6 - begin);
  std::string out;
  out.reserve(body.size() + body.size() / 8);
  std::size_t i = 0;
  while (i < body.size()) {
    const std::size_t lt = body.find('<', i);
    if (lt == std::string_view::npos) {
      out.append(body.substr(i));
      break;
    }
    out.append(body.substr(i, lt - i));
    if (StartsWith(body, lt, "<!--")) {
      const std::size_t close = body.find("-->", lt + 4);
      if (close == std::string_view::npos) rewriter.Fail("a comment is not closed");
      i = close + 3;  // comments are dropped
      continue;
    }
    if (StartsWith(body, lt, "<![CDATA[")) {
      const std::size_t close = body.find("]]>", lt);
      if (close == std::string_view::npos) rewriter.Fail("a CDATA section is not closed");
      out.append(body.substr(lt, close + 3 - lt));
      i = close + 3;
      continue;
    }
    if (StartsWith(body, lt, "<?") || StartsWith(body, lt, "<!")) {
      const std::size_t close = body.find('>', lt);
      if (close == std::string_view::npos) rewriter.Fail("a declaration is not closed");
      i = close + 1;  // processing instructions and declarations are dropped
      continue;
    }
    // A tag: up to its '>' outside quotes.
    std::size_t j = lt + 1;
    char quote = 0;
    while (j < body.size() && (quote || body[j] != '>')) {
      if (quote && body[j] == quote) quote = 0;
      else if (!quote && (body[j] == '"' || body[j] == '\'')) quote = body[j];
      ++j;
    }
    if (j >= body.size()) rewriter.Fail("a tag is not closed");
    const std::string_view tag = body.substr(lt, j + 1 - lt);
    if (Lower(tag.substr(0, 7)) == "<script") {
      const std::size_t close = Lower(body.substr(j)).find("</script>");
      i = close == std::string::npos ? body.size() : j + close + 9;
      continue;
    }
    rewriter.Tag(tag, out);
    i = j + 1;
  }
  return out;
}

}  // namespace covopt::internal
