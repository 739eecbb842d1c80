// parse_unique_fields: a repeated field refused by its path, whatever the nesting.
#include <catch2/catch.hpp>

#include <string>

#include "oracle/peers/json_fields.hpp"

using namespace dtlab;

namespace {

// The refusal's message, or "" when the text parses.
std::string refusal(const std::string& text) {
  try {
    parse_unique_fields(text);
  } catch (const DuplicateField& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("parse_unique_fields names the object of a repeated field by its path", "[json]") {
  CHECK(refusal(R"({"a": 1, "b": 2})").empty());
  CHECK(refusal(R"({"a": 1, "a": 2})") == "duplicate field 'a'");
  CHECK(refusal(R"({"cells": [{"site": 0}, {"site": 1, "site": 2}]})") == "cells[1]: duplicate field 'site'");
  // Elements before the object of every kind: numbers, arrays, objects.
  CHECK(refusal(R"({"x": [1, [2, 3], {"k": 4}, {"k": 5, "k": 6}]})") == "x[3]: duplicate field 'k'");
  CHECK(refusal(R"([[], {"a": {"b": 1, "b": 2}}])") == "[1].a: duplicate field 'b'");
  // The same name in sibling or nested objects is no repeat.
  CHECK(refusal(R"([{"a": 1}, {"a": {"a": 1}}])").empty());
}

TEST_CASE("parse_unique_fields on a wide object: every repeat found, past the small-object search", "[json]") {
  std::string wide = "{";
  for (int k = 0; k < 2000; ++k) wide += "\"f" + std::to_string(k) + "\": " + std::to_string(k) + ", ";
  CHECK(refusal(wide + "\"last\": 0}").empty());
  CHECK(refusal(wide + "\"f3\": 0}") == "duplicate field 'f3'");
  CHECK(refusal(wide + "\"f1999\": 0}") == "duplicate field 'f1999'");
}
