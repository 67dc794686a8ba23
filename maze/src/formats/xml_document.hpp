#pragma once
// An XML world file's elements, read by a streaming parser (expat) into a compact table.
//
// The world formats use three levels: <world>, its children (<wall>, <goal>, <boundary>,
// <landmark>, <startPositions>) and theirs (<pos>). The table keeps the root and the two
// levels below it; deeper elements are checked for well-formedness and dropped. No tree of
// the whole document is built: an element costs 40 bytes and an attribute 16 plus its value,
// so a file's table stays within about twice its size (a DOM took twelve times).
//
// Positions are the parser's: the 1-based line and column (in characters) of the tag's '<',
// and its byte offset in the text, from which an attribute's own place is found.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace maze::xml {

class Document;

// One element of a Document: a handle, valid while the Document lives.
class Element {
 public:
  std::string_view name() const;
  // The value as the parser delivers it (entities replaced), or nothing when it is absent.
  std::optional<std::string_view> attribute(std::string_view attribute_name) const;
  int line() const;
  int column() const;
  std::size_t offset() const;
  // The children named `child_name`, in document order (none below the table's depth).
  std::vector<Element> children(std::string_view child_name) const;
  std::optional<Element> first_child(std::string_view child_name) const;

 private:
  friend class Document;
  Element(const Document &doc, std::uint32_t index) : doc_(&doc), index_(index) {}
  const Document *doc_;
  std::uint32_t index_;
};

class Document {
 public:
  // Parses the whole text. Throws common::InputError "not well-formed XML: <the parser's
  // words>" at the parser's line and column, or "no XML element" for a text without one.
  static Document parse(std::string_view text, const std::string &file);

  Element root() const { return Element(*this, 0); }
  std::size_t element_count() const { return elements_.size(); }

 private:
  friend class Element;
  friend struct DocumentBuilder;
  static constexpr std::uint32_t kNone = UINT32_MAX;

  struct ElementRecord {
    std::uint32_t name;
    std::uint32_t first_child = kNone;
    std::uint32_t last_child = kNone;
    std::uint32_t next_sibling = kNone;
    std::uint32_t first_attribute;
    std::uint32_t attribute_count;
    std::int32_t line;
    std::int32_t column;
    std::uint64_t offset;
  };
  struct AttributeRecord {
    std::uint32_t name;
    std::uint32_t length;
    std::uint64_t value_begin;
  };

  std::uint32_t intern(std::string_view name);
  std::optional<std::uint32_t> name_id(std::string_view name) const;

  std::vector<ElementRecord> elements_;
  std::vector<AttributeRecord> attributes_;
  std::string values_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, std::uint32_t> name_ids_;
};

}  // namespace maze::xml
