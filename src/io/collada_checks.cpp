// The check of COLLADA files before import (mesh_file_checks.h).
#include "mesh_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "freespace/input_error.h"
#include "mesh_text.h"

namespace freespace::detail {

namespace {

constexpr int kDeepestCollada = 256;

// Calls visit(element, depth) for every element, depth first, without recursion.
template <class Visitor>
void forEachElement(const pugi::xml_node& root, Visitor visit) {
  std::vector<std::pair<pugi::xml_node, int>> stack{{root, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (node.type() == pugi::node_element) visit(node, depth);
    for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling()) {
      stack.emplace_back(child, depth + 1);
    }
  }
}

// Calls visit(word) for each whitespace-separated word of the text.
template <class Visitor>
void forEachWord(const char* text, Visitor visit) {
  while (*text) {
    while (*text && std::isspace(static_cast<unsigned char>(*text))) ++text;
    const char* start = text;
    while (*text && !std::isspace(static_cast<unsigned char>(*text))) ++text;
    if (text > start) visit(std::string_view(start, static_cast<std::size_t>(text - start)));
  }
}

std::size_t countWords(const char* text) {
  std::size_t count = 0;
  forEachWord(text, [&](std::string_view) { ++count; });
  return count;
}

// The first word of an array's text that is not a number of its kind: decimal (as
// the import library reads them) in a <float_array>, whole in an <int_array>.
std::string firstNonNumber(const char* text, bool floats) {
  std::string bad;
  forEachWord(text, [&](std::string_view word) {
    double number = 0;
    std::int64_t whole = 0;
    if (bad.empty() && !(floats ? parseNumber(word, number) : parseWhole(word, whole))) bad = std::string(word);
  });
  return bad;
}

std::string elementDefect(const pugi::xml_node& element, const std::string& defect) {
  const std::string id = element.attribute("id").value();
  return "COLLADA <" + printable(element.name()) + (id.empty() ? "" : " id=\"" + printable(id) + "\"") + ">: " + defect;
}

// Nodes reachable from each node through nested nodes and <instance_node>: a cycle
// makes the import library recurse for ever.
void requireNoInstanceCycle(const std::string& path, const pugi::xml_document& document) {
  std::map<std::string, pugi::xml_node> byId;
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    if (std::strcmp(element.name(), "node") == 0 && element.attribute("id")) byId[element.attribute("id").value()] = element;
  });
  // The nodes a node leads to: its nested nodes and the nodes it instances.
  const auto successors = [&](const pugi::xml_node& node) {
    std::vector<pugi::xml_node> next;
    for (const pugi::xml_node& child : node.children()) {
      if (std::strcmp(child.name(), "node") == 0) next.push_back(child);
      if (std::strcmp(child.name(), "instance_node") != 0) continue;
      const std::string url = child.attribute("url").value();
      const auto target = url.rfind('#', 0) == 0 ? byId.find(url.substr(1)) : byId.end();
      if (target != byId.end()) next.push_back(target->second);
    }
    return next;
  };
  std::map<const void*, int> state;  // 1 on the walk, 2 done
  forEachElement(document, [&](const pugi::xml_node& start, int) {
    if (std::strcmp(start.name(), "node") != 0 || state[start.internal_object()] != 0) return;
    std::vector<std::pair<pugi::xml_node, std::vector<pugi::xml_node>>> walk{{start, successors(start)}};
    state[start.internal_object()] = 1;
    while (!walk.empty()) {
      auto& [node, next] = walk.back();
      if (next.empty()) {
        state[node.internal_object()] = 2;
        walk.pop_back();
        continue;
      }
      const pugi::xml_node successor = next.back();
      next.pop_back();
      const int seen = state[successor.internal_object()];
      if (seen == 1) throw InputError(path, elementDefect(successor, "instances itself (through <instance_node>)"));
      if (seen == 0) {
        state[successor.internal_object()] = 1;
        walk.emplace_back(successor, successors(successor));
      }
    }
  });
}

// Every id of the geometry's data (sources, vertices and arrays, which primitives'
// inputs and accessors reference by `#id`) names one of them: the import library,
// given two sources of one id (the second without an array), read through a null
// array and crashed (found by fuzzing). Exporters give a geometry and its scene node
// one id, which the library resolves apart: that is kept.
void requireUniqueDataIds(const std::string& path, const pugi::xml_document& document) {
  std::map<std::string, int> seen;
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const std::string name = element.name();
    const bool data = name == "source" || name == "vertices" || name == "float_array" || name == "int_array";
    const pugi::xml_attribute id = element.attribute("id");
    if (data && id && ++seen[id.value()] == 2) {
      throw InputError(path, elementDefect(element, "its id names other data too (ids must be unique)"));
    }
  });
}

// Whole numbers in [0, limit) only; false at the first other word.
bool indicesBelow(const char* text, long double limit) {
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    std::int64_t value = 0;
    if (!parseWhole(word, value) || value < 0 || static_cast<long double>(value) >= limit) return false;
  }
  return true;
}

// <float_array> and <int_array> numbers and counts, <accessor> reach and index lists.
void requireConsistentArrays(const std::string& path, const pugi::xml_document& document) {
  std::map<std::string, std::size_t> arraySizes;
  std::size_t values = 0;
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const bool floats = std::strcmp(element.name(), "float_array") == 0;
    if (!floats && std::strcmp(element.name(), "int_array") != 0) return;
    const std::size_t words = countWords(element.child_value());
    if (const std::string bad = firstNonNumber(element.child_value(), floats); !bad.empty()) {
      throw InputError(path, elementDefect(element, "'" + printable(bad) + "' is not " +
                                                        (floats ? "a decimal number" : "a whole number")));
    }
    std::int64_t count = -1;
    if (!parseWhole(element.attribute("count").value(), count) || count != static_cast<std::int64_t>(words)) {
      throw InputError(path, elementDefect(element, "count=\"" + printable(element.attribute("count").value()) +
                                                        "\" but " + std::to_string(words) + " values"));
    }
    if (element.attribute("id")) arraySizes[element.attribute("id").value()] = words;
    values += words;
  });
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const std::string name = element.name();
    if (name == "accessor") {
      const std::string source = element.attribute("source").value();
      const auto array = source.rfind('#', 0) == 0 ? arraySizes.find(source.substr(1)) : arraySizes.end();
      std::int64_t count = 0, stride = 1, offset = 0;
      const bool numbers = parseWhole(element.attribute("count").value(), count) &&
                           (!element.attribute("stride") || parseWhole(element.attribute("stride").value(), stride)) &&
                           (!element.attribute("offset") || parseWhole(element.attribute("offset").value(), offset));
      if (array == arraySizes.end()) {
        throw InputError(path, elementDefect(element, "source=\"" + printable(source) + "\" names no array of the file"));
      }
      if (!numbers || count < 0 || stride < 1 || offset < 0 ||
          static_cast<long double>(count) * stride + offset > static_cast<long double>(array->second)) {
        throw InputError(path, elementDefect(element, "reads beyond its array"));
      }
    } else if ((name == "p" || name == "v" || name == "vcount" || name == "h") &&
               !indicesBelow(element.child_value(), std::max<long double>(values, countWords(element.child_value())))) {
      throw InputError(path, elementDefect(element.parent(), "<" + name + "> holds something other than indices of "
                                                             "the file's values"));
    }
  });
}

// The values a primitive element's index lists must hold: the count of its
// primitives times the corners each takes, times the inputs' stride (the largest
// input offset plus one); <polylist> takes its corners from <vcount>, the
// one-list-per-primitive kinds count their lists.
void requireCompletePrimitives(const std::string& path, const pugi::xml_document& document) {
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const std::string name = element.name();
    const bool oneList = name == "triangles" || name == "lines" || name == "polylist";
    const bool listEach = name == "polygons" || name == "trifans" || name == "tristrips" || name == "linestrips";
    if (!oneList && !listEach) return;
    std::int64_t count = 0;
    if (!parseWhole(element.attribute("count").value(), count) || count < 0) {
      throw InputError(path, elementDefect(element, "count is not a whole number"));
    }
    if (listEach) {
      std::int64_t lists = 0;
      for (const pugi::xml_node& child : element.children()) lists += std::strcmp(child.name(), "p") == 0 || std::strcmp(child.name(), "ph") == 0;
      if (lists != count) {
        throw InputError(path, elementDefect(element, "count=\"" + std::to_string(count) + "\" but " +
                                                          std::to_string(lists) + " <p> lists"));
      }
      return;
    }
    std::int64_t stride = 1;
    for (const pugi::xml_node& input : element.children("input")) {
      std::int64_t offset = 0;
      if (input.attribute("offset") && (!parseWhole(input.attribute("offset").value(), offset) || offset < 0 || offset > 64)) {
        throw InputError(path, elementDefect(element, "an <input> offset is not a small whole number"));
      }
      stride = std::max(stride, offset + 1);
    }
    long double corners = static_cast<long double>(count) * (name == "triangles" ? 3 : 2);
    if (name == "polylist") {
      const pugi::xml_node vcount = element.child("vcount");
      std::istringstream words(vcount.child_value());
      corners = 0;
      std::int64_t polygons = 0;
      for (std::string word; words >> word; ++polygons) {
        std::int64_t size = 0;
        if (!parseWhole(word, size) || size < 1) {
          throw InputError(path, elementDefect(element, "<vcount> holds '" + printable(word) + "'"));
        }
        corners += static_cast<long double>(size);
      }
      if (!vcount || polygons != count) {
        throw InputError(path, elementDefect(element, "count=\"" + std::to_string(count) + "\" but " +
                                                          std::to_string(polygons) + " sizes in <vcount>"));
      }
    }
    const long double values = static_cast<long double>(countWords(element.child("p").child_value()));
    if (count > 0 && values != corners * static_cast<long double>(stride)) {
      std::ostringstream text;
      text << static_cast<double>(corners) << " corners of " << stride << " indices each need "
           << static_cast<double>(corners * stride) << " values in <p>, it has " << static_cast<double>(values);
      throw InputError(path, elementDefect(element, text.str()));
    }
  });
}

}  // namespace

void checkColladaFile(const std::string& path, const std::string& content) {
  // XML allows no other control characters; the import library looped for ever on a
  // vertical tab between indices.
  requirePlainText(path, content, "COLLADA", false);
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(content.data(), content.size());
  if (!parsed) {
    throw InputError(path, "COLLADA file is not well-formed XML at byte " + std::to_string(parsed.offset) + ": " +
                               parsed.description());
  }
  forEachElement(document, [&](const pugi::xml_node& element, int depth) {
    if (depth > kDeepestCollada) {
      throw InputError(path, "COLLADA elements nested deeper than " + std::to_string(kDeepestCollada) + " (<" +
                                 printable(element.name()) + ">)");
    }
  });
  requireUniqueDataIds(path, document);
  requireNoInstanceCycle(path, document);
  requireConsistentArrays(path, document);
  requireCompletePrimitives(path, document);
}

}  // namespace freespace::detail
