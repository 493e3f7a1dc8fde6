// Vertex selections: which vertices of an OBJ mesh a command acts on (join's paste by chosen
// vertices), as 1-based OBJ vertex numbers (the "v" records in file order, as a modeller
// shows them): single numbers and ranges "a-b" (both ends included).
//
// A selection file holds numbers and ranges separated by blanks or commas, any number per
// line; a line whose first token starts with '#' is a comment, and a token starting with '#'
// ends its line. A command-line list is the same text on one line ("12,15,40-52").
// The result is 0-based, sorted, without repeats (a repeat is harmless).
#pragma once
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace tessera {

// Throws InputError naming the file and line: Io when the file cannot be read, Syntax for a
// token that is no number or range, Range for 0, a number past `vertexCount` or a range that
// runs backwards, Count for a file that names no vertex.
std::vector<uint32_t> readVertexSelection(const std::string& path, uint32_t vertexCount);
std::vector<uint32_t> parseVertexSelection(std::istream& in, const std::string& nameForMessages,
                                           uint32_t vertexCount);

// A command-line list; throws std::invalid_argument naming the token and the reason, as above.
std::vector<uint32_t> parseVertexList(const std::string& text, uint32_t vertexCount);
// The list's form alone, before the mesh is read (any number ≥ 1 passes): what
// parseVertexList would refuse for every mesh.
void checkVertexList(const std::string& text);

}  // namespace tessera
