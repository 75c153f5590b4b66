#pragma once
// Python values as scene values: the text of a --set (load_scene's
// overrides) and the TOML value of a scene file (Scene(joint={...})). Only
// what a scene key can hold: a number, a bool, a text.

#include <string>

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

namespace railjoint::python {

/// The value part of `--set section.key=value`: an int or a float in its
/// shortest exact form, True/False as true/false, a str as the command line
/// gives it (a bare word is text, "30" a number, '"30"' the text 30); a
/// NumPy scalar or one-element array as the value it holds. Throws
/// InputError naming `file` and `key` for a text with a line break, a
/// TypeError (pybind11::type_error) naming them for any other type.
std::string override_text(const pybind11::handle& value, const std::string& file, const std::string& key);

/// Sets table[key] to the value as a scene file types it (a str is text).
/// Throws a TypeError naming `file` and `dotted_key` for any other type.
void insert_scene_value(toml::table& table, const std::string& key, const pybind11::handle& value,
                        const std::string& file, const std::string& dotted_key);

/// Whether the value is True/False (a NumPy bool_ too): what the scene
/// reader refuses for a number key is then a TypeError.
bool is_boolean(const pybind11::handle& value);

}  // namespace railjoint::python
