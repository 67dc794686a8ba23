#include "xml_document.hpp"

#include <algorithm>
#include <exception>
#include <limits>
#include <memory>

#include <expat.h>
#include <fmt/format.h>

#include "common/error.hpp"

namespace maze::xml {

namespace {

// The table's depth: <world>, its children and theirs.
constexpr int kKeptDepth = 3;
// Text handed to the parser at a time.
constexpr std::size_t kChunk_bytes = std::size_t{1} << 20;

struct ParserDeleter {
  void operator()(XML_ParserStruct *p) const { XML_ParserFree(p); }
};

}  // namespace

// Expat's callbacks filling a Document; an exception inside one (out of memory) stops the
// parser and is rethrown once expat has returned, never thrown through its C frames.
struct DocumentBuilder {
  Document &doc;
  XML_Parser parser;
  struct OpenTag {
    std::string name;
    int line;
    std::uint32_t kept;  // its index in the table, or kNone below the table's depth
  };
  std::vector<OpenTag> open;  // the elements enclosing the parser's position, outermost first
  std::exception_ptr failure;
  int bom_columns = 0;  // expat counts a byte-order mark as a column of line 1; readers do not

  int column() const {
    const auto line = XML_GetCurrentLineNumber(parser);
    return static_cast<int>(XML_GetCurrentColumnNumber(parser)) + 1 - (line == 1 ? bom_columns : 0);
  }

  void start(const XML_Char *name, const XML_Char **atts) {
    const auto line = static_cast<int>(XML_GetCurrentLineNumber(parser));
    if (open.size() >= kKeptDepth) {
      open.push_back({name, line, Document::kNone});
      return;
    }
    Document::ElementRecord rec{};
    rec.name = doc.intern(name);
    rec.first_child = rec.last_child = rec.next_sibling = Document::kNone;
    rec.first_attribute = static_cast<std::uint32_t>(doc.attributes_.size());
    rec.line = line;
    rec.column = column();
    rec.offset = static_cast<std::uint64_t>(XML_GetCurrentByteIndex(parser));
    for (const XML_Char **a = atts; a[0] != nullptr; a += 2) {
      const std::string_view value(a[1]);
      doc.attributes_.push_back({doc.intern(a[0]), static_cast<std::uint32_t>(value.size()), doc.values_.size()});
      doc.values_.append(value);
    }
    rec.attribute_count = static_cast<std::uint32_t>(doc.attributes_.size()) - rec.first_attribute;
    if (doc.elements_.size() >= std::numeric_limits<std::uint32_t>::max() - 1) {
      throw common::InputError("more than 4 billion XML elements");
    }
    const auto index = static_cast<std::uint32_t>(doc.elements_.size());
    doc.elements_.push_back(rec);
    if (!open.empty()) {
      Document::ElementRecord &parent = doc.elements_[open.back().kept];
      if (parent.last_child == Document::kNone) {
        parent.first_child = index;
      } else {
        doc.elements_[parent.last_child].next_sibling = index;
      }
      parent.last_child = index;
    }
    open.push_back({name, line, index});
  }

  void end() { open.pop_back(); }

  // Expat's words, with what an unclosed element or a mismatched end tag is about.
  std::string error_words(std::string_view text) const {
    const XML_Error code = XML_GetErrorCode(parser);
    // Expat's "not well-formed (invalid token)" follows our "not well-formed XML: ".
    std::string words = code == XML_ERROR_INVALID_TOKEN ? "invalid token" : XML_ErrorString(code);
    if (open.empty()) return words;
    const OpenTag &inner = open.back();
    if (code == XML_ERROR_NO_ELEMENTS) return fmt::format("the file ends inside <{}> of line {}", inner.name, inner.line);
    if (code == XML_ERROR_TAG_MISMATCH) {
      const auto at = static_cast<std::size_t>(XML_GetCurrentByteIndex(parser));
      const std::size_t lt = at < text.size() ? text.rfind('<', at) : std::string_view::npos;
      const std::string_view tag = lt == std::string_view::npos ? std::string_view() : text.substr(lt);
      const std::size_t end = tag.find_first_of(" \t\r\n>");
      if (tag.starts_with("</") && end != std::string_view::npos) {
        words += fmt::format(": {}> where <{}> of line {} is open", tag.substr(0, end), inner.name, inner.line);
      }
    }
    return words;
  }

  static void on_start(void *self, const XML_Char *name, const XML_Char **atts) {
    auto &b = *static_cast<DocumentBuilder *>(self);
    try {
      b.start(name, atts);
    } catch (...) {
      b.failure = std::current_exception();
      XML_StopParser(b.parser, XML_FALSE);
    }
  }
  static void on_end(void *self, const XML_Char *) { static_cast<DocumentBuilder *>(self)->end(); }
};

Document Document::parse(std::string_view text, const std::string &file) {
  const std::unique_ptr<XML_ParserStruct, ParserDeleter> parser(XML_ParserCreate(nullptr));
  if (!parser) throw std::bad_alloc();
  Document doc;
  DocumentBuilder builder{doc, parser.get(), {}, {}, text.starts_with("\xEF\xBB\xBF") ? 1 : 0};
  XML_SetUserData(parser.get(), &builder);
  XML_SetElementHandler(parser.get(), &DocumentBuilder::on_start, &DocumentBuilder::on_end);
  std::size_t at = 0;
  XML_Status status = XML_STATUS_OK;
  do {
    const std::size_t n = std::min(kChunk_bytes, text.size() - at);
    const bool last = at + n == text.size();
    status = XML_Parse(parser.get(), text.data() + at, static_cast<int>(n), last ? 1 : 0);
    at += n;
    if (last) break;
  } while (status == XML_STATUS_OK);
  if (builder.failure) std::rethrow_exception(builder.failure);
  if (status != XML_STATUS_OK) {
    if (XML_GetErrorCode(parser.get()) == XML_ERROR_NO_ELEMENTS && doc.elements_.empty()) {
      throw common::InputError(common::SourceLocation{file, 0, 0}, "no XML element: expected <world>");
    }
    throw common::InputError(
        common::SourceLocation{file, static_cast<int>(XML_GetErrorLineNumber(parser.get())), builder.column()},
        fmt::format("not well-formed XML: {}", builder.error_words(text)));
  }
  return doc;
}

std::uint32_t Document::intern(std::string_view name) {
  const auto [it, added] = name_ids_.try_emplace(std::string(name), static_cast<std::uint32_t>(names_.size()));
  if (added) names_.emplace_back(name);
  return it->second;
}

std::optional<std::uint32_t> Document::name_id(std::string_view name) const {
  const auto it = name_ids_.find(std::string(name));
  if (it == name_ids_.end()) return std::nullopt;
  return it->second;
}

std::string_view Element::name() const { return doc_->names_[doc_->elements_[index_].name]; }

std::optional<std::string_view> Element::attribute(std::string_view attribute_name) const {
  const std::optional<std::uint32_t> id = doc_->name_id(attribute_name);
  if (!id) return std::nullopt;
  const Document::ElementRecord &rec = doc_->elements_[index_];
  for (std::uint32_t i = rec.first_attribute; i < rec.first_attribute + rec.attribute_count; ++i) {
    const Document::AttributeRecord &a = doc_->attributes_[i];
    if (a.name == *id) return std::string_view(doc_->values_).substr(a.value_begin, a.length);
  }
  return std::nullopt;
}

int Element::line() const { return doc_->elements_[index_].line; }
int Element::column() const { return doc_->elements_[index_].column; }
std::size_t Element::offset() const { return static_cast<std::size_t>(doc_->elements_[index_].offset); }

std::vector<Element> Element::children(std::string_view child_name) const {
  std::vector<Element> found;
  const std::optional<std::uint32_t> id = doc_->name_id(child_name);
  if (!id) return found;
  for (std::uint32_t i = doc_->elements_[index_].first_child; i != Document::kNone;
       i = doc_->elements_[i].next_sibling) {
    if (doc_->elements_[i].name == *id) found.push_back(Element(*doc_, i));
  }
  return found;
}

std::optional<Element> Element::first_child(std::string_view child_name) const {
  const std::optional<std::uint32_t> id = doc_->name_id(child_name);
  if (!id) return std::nullopt;
  for (std::uint32_t i = doc_->elements_[index_].first_child; i != Document::kNone;
       i = doc_->elements_[i].next_sibling) {
    if (doc_->elements_[i].name == *id) return Element(*doc_, i);
  }
  return std::nullopt;
}

}  // namespace maze::xml
