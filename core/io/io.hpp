// Reading and writing hex complexes: VTK legacy (ASCII/binary, cell types 12 and 11),
// Medit .mesh (Vertices + Hexahedra), and the lossless native format (.hxd) with explicit gluings.
// Readers are all-or-nothing: on error they throw Error naming the file, line (or byte) and reason.
#pragma once
#include <string>
#include <string_view>

#include "complex/complex.hpp"

namespace hexdual::io {

enum class Format { Vtk, Medit, Native };

// Format from a file name's extension (.vtk, .mesh, .hxd); throws for anything else.
Format formatFromPath(const std::string& path);
// Format from the first bytes of a file; throws when none matches.
Format detectFormat(std::string_view data, const std::string& name);
const char* formatName(Format f);

Complex readVtk(std::string_view data, const std::string& name);
Complex readMedit(std::string_view data, const std::string& name);
Complex readNative(std::string_view data, const std::string& name);
Complex readMesh(std::string_view data, const std::string& name);  // detects the format

// Writers number the live vertices and hexes densely, in id order.
std::string writeVtk(const Complex& cx, bool binary = false);
std::string writeMedit(const Complex& cx);
std::string writeNative(const Complex& cx);
std::string writeMesh(const Complex& cx, Format f, bool binary = false);

Complex readFile(const std::string& path);
void writeFile(const Complex& cx, const std::string& path, bool binary = false);

}  // namespace hexdual::io
