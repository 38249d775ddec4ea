// SPDX-License-Identifier: GPL-3.0-or-later
// The checks made before Assimp reads a file (see assimp_prechecks.h).
#include "core/io/assimp/assimp_prechecks.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace core::detail::assimp {

namespace fs = std::filesystem;

/**
 * OBJ syntax Assimp forgives silently: a face statement without vertices. Such a file is
 * malformed (truncated or hand-broken), so it is refused instead of loading with a hole.
 */
Status checkObjFaces(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line, logical;
    std::uint64_t lineNo = 0, startLine = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (logical.empty())
            startLine = lineNo;
        if (!line.empty() && line.back() == '\\') { // continued on the next line
            line.pop_back();
            logical += line + " ";
            continue;
        }
        logical += line;
        const std::size_t hash = logical.find('#');
        if (hash != std::string::npos)
            logical.resize(hash);
        const std::size_t b = logical.find_first_not_of(" \t");
        if (b != std::string::npos && logical[b] == 'f' &&
            (b + 1 == logical.size() || logical[b + 1] == ' ' || logical[b + 1] == '\t') &&
            logical.find_first_not_of(" \t", b + 1) == std::string::npos)
            return Error{"line " + std::to_string(startLine) + ": a face without vertices",
                         ErrorKind::BadInput};
        logical.clear();
    }
    return {};
}

/** The first bytes of a file (headers are small). */
std::string readHead(const fs::path& file, std::size_t max) {
    std::ifstream in(file, std::ios::binary);
    std::string head(max, '\0');
    in.read(head.data(), static_cast<std::streamsize>(max));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return head;
}

/** A decimal count, or false when absent or absurdly long. */
bool parseCount(const std::string& token, std::uint64_t& out) {
    if (token.empty() || token.size() > 19 ||
        !std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isdigit(c); }))
        return false;
    out = std::stoull(token);
    return true;
}

/**
 * A count as Assimp's OFF reader takes it: the token's leading digits, whatever follows them
 * ("1000storage" is 1000), saturating instead of wrapping. False when it starts with no digit.
 */
bool parseLeadingCount(const std::string& token, std::uint64_t& out) {
    std::size_t digits = 0;
    while (digits < token.size() && std::isdigit(static_cast<unsigned char>(token[digits])))
        ++digits;
    if (digits == 0)
        return false;
    out = 0;
    for (std::size_t k = 0; k < digits; ++k) {
        const std::uint64_t digit = std::uint64_t(token[k] - '0');
        if (out > (std::numeric_limits<std::uint64_t>::max() - digit) / 10) {
            out = std::numeric_limits<std::uint64_t>::max();
            return true;
        }
        out = out * 10 + digit;
    }
    return true;
}

std::string tooManyElements(std::uint64_t count, const std::string& what, std::uint64_t size) {
    return "the header declares " + std::to_string(count) + " " + what + ", more than the " +
           std::to_string(size) + "-byte file can hold";
}

/**
 * Text OFF: every face lists as many vertex indices as its first number says, each a vertex of
 * the file, and the faces the header declares are there. Assimp 5.2 reads on past a short face
 * line, into the next lines and past the end of its buffer (found by fuzzing). Files that are not
 * text OFF, or whose header cannot be read here, are left to Assimp.
 */
Status checkOffFaces(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    std::vector<std::string> tokens;
    enum class Stage { Magic, Counts, Vertices, Faces } stage = Stage::Magic;
    bool dimension = false;
    std::uint64_t vertices = 0, faces = 0, seenVertices = 0, seenFaces = 0, lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (const std::size_t hash = line.find('#'); hash != std::string::npos)
            line.resize(hash);
        tokens.clear();
        std::istringstream words(line);
        for (std::string w; words >> w;)
            tokens.push_back(w);
        if (tokens.empty())
            continue;
        std::size_t t = 0;
        if (stage == Stage::Magic) {
            const std::string& magic = tokens[0];
            if (magic.size() < 3 || magic.size() > 9 ||
                magic.compare(magic.size() - 3, 3, "OFF") != 0 ||
                (tokens.size() > 1 && tokens[1] == "BINARY"))
                return {};
            dimension = magic.find('n') != std::string::npos;
            stage = Stage::Counts;
            t = 1;
            if (t == tokens.size())
                continue;
        }
        if (stage == Stage::Counts) {
            if (dimension) {
                ++t; // nOFF: the dimension comes first
                dimension = false;
                if (t >= tokens.size())
                    continue;
            }
            if (t + 1 >= tokens.size() || !parseCount(tokens[t], vertices) ||
                !parseCount(tokens[t + 1], faces))
                return {};
            stage = vertices > 0 ? Stage::Vertices : Stage::Faces;
            continue;
        }
        if (stage == Stage::Vertices) {
            if (++seenVertices == vertices)
                stage = Stage::Faces;
            continue;
        }
        if (seenFaces == faces)
            break;
        ++seenFaces;
        std::uint64_t corners = 0;
        if (!parseCount(tokens[0], corners))
            return Error{"line " + std::to_string(lineNo) +
                             ": an OFF face must start with its number of vertices",
                         ErrorKind::BadInput};
        if (tokens.size() < corners + 1)
            return Error{"line " + std::to_string(lineNo) + ": the face lists " +
                             std::to_string(tokens.size() - 1) +
                             " vertex indices but says it has " + std::to_string(corners),
                         ErrorKind::BadInput};
        for (std::size_t k = 1; k <= corners; ++k) {
            std::uint64_t index = 0;
            if (!parseCount(tokens[k], index) || index >= vertices)
                return Error{"line " + std::to_string(lineNo) + ": the face uses vertex \"" +
                                 tokens[k] + "\", which is not one of the file's " +
                                 std::to_string(vertices) + " vertices",
                             ErrorKind::BadInput};
        }
    }
    if (stage == Stage::Faces && seenFaces < faces)
        return Error{"the OFF file ends after " + std::to_string(seenFaces) + " of the " +
                         std::to_string(faces) + " faces its header declares",
                     ErrorKind::BadInput};
    return {};
}

/** head's whitespace-separated tokens, '#' comments dropped; at most about 4096 of them. */
std::vector<std::string> headerTokens(const std::string& head) {
    std::vector<std::string> tokens;
    std::string token;
    bool comment = false;
    for (char c : head) {
        if (c == '\n' || c == '\r')
            comment = false;
        if (comment)
            continue;
        if (c == '#') {
            comment = true;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            if (!token.empty())
                tokens.push_back(std::move(token));
            token.clear();
        } else {
            token += c;
        }
        if (tokens.size() > 4096)
            break;
    }
    if (!token.empty())
        tokens.push_back(token);
    return tokens;
}

/** OFF: [ST][C][N][4][n]OFF, then (for nOFF) a dimension, then vertex, face, edge counts. */
bool isOffMagic(const std::string& magic) {
    return magic.size() >= 3 && magic.size() <= 9 && magic.compare(magic.size() - 3, 3, "OFF") == 0;
}

Status checkOffCounts(const std::vector<std::string>& tokens, std::uint64_t fileSize,
                      std::uint64_t maxRaw) {
    const std::string& magic = tokens[0];
    std::size_t t = 1;
    if (t < tokens.size() && tokens[t] == "BINARY")
        return {}; // Assimp refuses binary OFF itself
    if (magic.find('n') != std::string::npos)
        ++t;
    // Assimp reads both counts by their leading digits (a face count of "1000storage" is
    // 1000, found by fuzzing: a 169-byte file made it allocate 25 GB), and allocates the
    // vertices first.
    std::uint64_t vertices = 0, faces = 0;
    if (t >= tokens.size() || !parseLeadingCount(tokens[t], vertices))
        return {};
    if (vertices > maxRaw)
        return Error{"too many vertices (the header declares " + std::to_string(vertices) + ")",
                     ErrorKind::BadInput};
    // "0 0 0\n" is the shortest vertex line, "0\n" the shortest face line.
    if (vertices > fileSize / 6)
        return Error{tooManyElements(vertices, "vertices", fileSize), ErrorKind::BadInput};
    if (t + 1 >= tokens.size() || !parseLeadingCount(tokens[t + 1], faces))
        return {};
    if (faces > fileSize / 2)
        return Error{tooManyElements(faces, "faces", fileSize), ErrorKind::BadInput};
    return {};
}

/** Bytes of a PLY scalar type; 0 for a word that is not one. */
std::uint64_t plyTypeSize(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
        return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
        return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" ||
        t == "float32")
        return 4;
    if (t == "double" || t == "float64")
        return 8;
    return 0; // not a PLY type
}

/** A PLY header's elements, each with the fewest bytes one of them can take. */
struct PlyHeaderCounts {
    struct Element {
        std::string name;
        std::uint64_t count = 0;
        std::uint64_t minBytes = 0;
    };
    std::vector<Element> elements;
    std::uint64_t bodyStart = 0; // the first byte after end_header
};

/**
 * The PLY header in head, line by line; it must be well formed: Assimp 5.2 hangs or reads wild
 * on unknown keywords, counts like "0.0" and headers without end_header (found by fuzzing).
 */
Status readPlyHeaderCounts(const std::string& head, PlyHeaderCounts& out) {
    bool ascii = true;
    bool ended = false;
    std::size_t lineStart = 0;
    for (int lineNo = 1; lineStart < head.size() && !ended; ++lineNo) {
        std::size_t lineEnd = head.find('\n', lineStart);
        if (lineEnd == std::string::npos)
            break; // the header runs past what was read, or the file ends in it
        std::istringstream words(head.substr(lineStart, lineEnd - lineStart));
        lineStart = lineEnd + 1;
        std::vector<std::string> w;
        for (std::string word; words >> word;)
            w.push_back(word);
        const std::string where = "line " + std::to_string(lineNo) + " of the PLY header: ";
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info" ||
            (lineNo == 1 && w[0].rfind("ply", 0) == 0))
            continue;
        if (w[0] == "format" && w.size() == 3) {
            ascii = w[1] == "ascii";
        } else if (w[0] == "element" && w.size() == 3) {
            PlyHeaderCounts::Element e;
            e.name = w[1];
            if (!parseCount(w[2], e.count))
                return Error{where + "the element \"" + e.name +
                                 "\" has a count that is not a whole number (\"" + w[2] + "\")",
                             ErrorKind::BadInput};
            out.elements.push_back(e);
        } else if (w[0] == "property" && !out.elements.empty() &&
                   ((w.size() == 3 && plyTypeSize(w[1]) > 0) ||
                    (w.size() == 5 && w[1] == "list" && plyTypeSize(w[2]) > 0 &&
                     plyTypeSize(w[3]) > 0))) {
            // A list costs at least its (zero) count; a scalar its size.
            out.elements.back().minBytes += ascii ? 2 : plyTypeSize(w.size() == 5 ? w[2] : w[1]);
        } else if (w[0] == "end_header" && w.size() == 1) {
            ended = true;
            out.bodyStart = lineStart;
        } else if (w[0] == "format" || w[0] == "element" || w[0] == "property" ||
                   w[0] == "end_header") {
            return Error{where + "\"" + w[0] + "\" is not followed by what it needs",
                         ErrorKind::BadInput};
        }
        // Other lines are skipped, as Assimp does (exporters write free text there).
    }
    if (!ended)
        return Error{"the PLY header does not end (no end_header line in its first " +
                         std::to_string(head.size()) + " bytes)",
                     ErrorKind::BadInput}; // Assimp would read on and hang
    return {};
}

/** PLY: the sum over elements of count * the smallest size one element can have fits the body. */
Status checkPlyCounts(const PlyHeaderCounts& header, std::uint64_t fileSize, std::uint64_t maxRaw) {
    const std::uint64_t body = fileSize > header.bodyStart ? fileSize - header.bodyStart : 0;
    for (const PlyHeaderCounts::Element& e : header.elements)
        if (e.count > 0 && e.minBytes == 0) // Assimp would loop over them without moving on
            return Error{"the PLY header declares " + std::to_string(e.count) + " \"" + e.name +
                             "\" elements without properties",
                         ErrorKind::BadInput};
    std::uint64_t needed = 0;
    for (const PlyHeaderCounts::Element& e : header.elements) {
        if (e.name == "vertex" && e.count > maxRaw)
            return Error{"too many vertices (the header declares " + std::to_string(e.count) + ")",
                         ErrorKind::BadInput};
        std::uint64_t bytes = 0;
        if (__builtin_mul_overflow(e.count, std::max<std::uint64_t>(e.minBytes, 1), &bytes) ||
            __builtin_add_overflow(needed, bytes, &needed) || needed > body)
            return Error{tooManyElements(e.count, "\"" + e.name + "\" elements", fileSize),
                         ErrorKind::BadInput};
    }
    return {};
}

/**
 * OFF and PLY headers declare element counts that Assimp allocates and loops over before it
 * notices the data is missing: a 300-byte file can cost gigabytes and minutes. The counts must
 * fit the file: an ASCII value takes at least 2 bytes ("0 "), a binary one its size.
 */
Status checkDeclaredCounts(const fs::path& file, std::uint64_t fileSize, const LoadLimits& limits) {
    const std::string head = readHead(file, 65536);
    const std::vector<std::string> tokens = headerTokens(head);
    if (tokens.empty())
        return {};
    const std::uint64_t maxRaw = limits.maxVertices * 4;
    if (isOffMagic(tokens[0]))
        return checkOffCounts(tokens, fileSize, maxRaw);
    // PLY: Assimp takes any file that starts with the three letters for PLY ("ply," too).
    if (tokens[0].rfind("ply", 0) != 0)
        return {};
    PlyHeaderCounts header;
    if (Status read = readPlyHeaderCounts(head, header); !read)
        return read;
    return checkPlyCounts(header, fileSize, maxRaw);
}

} // namespace core::detail::assimp
