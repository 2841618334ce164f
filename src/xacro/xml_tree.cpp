// The xacro document tree: parsing with expat (keeping line numbers), in-place editing, and
// xacro's pretty printer.
#include "xacro/internal/xml_tree.h"

#include <expat.h>
#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include "common/error.h"
#include "common/file_reading.h"

namespace urdfsnap::xacro {

const std::string* Node::Attribute(const std::string& key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

void Node::SetAttribute(const std::string& key, std::string value) {
  for (auto& [k, v] : attributes) {
    if (k == key) {
      v = std::move(value);
      return;
    }
  }
  attributes.emplace_back(key, std::move(value));
}

void Node::RemoveAttribute(const std::string& key) {
  attributes.erase(std::remove_if(attributes.begin(), attributes.end(), [&](const auto& kv) { return kv.first == key; }),
                   attributes.end());
}

Node* Node::FirstChildElement() const {
  Node* c = first;
  while (c && c->type != Type::kElement) c = c->next;
  return c;
}

Node* Node::NextSiblingElement() const {
  Node* c = next;
  while (c && c->type != Type::kElement) c = c->next;
  return c;
}

Node* NodePool::Allocate(Node::Type type) {
  Account(sizeof(Node));
  if (!free_.empty()) {
    Node* node = free_.back();
    free_.pop_back();
    node->type = type;
    node->name.clear();
    node->data.clear();
    node->attributes.clear();
    node->parent = node->first = node->last = node->prev = node->next = nullptr;
    node->file = -1;
    node->line = 0;
    return node;
  }
  if (blocks_.empty() || used_in_block_ == blocks_.back().capacity) AddBlock();
  Node* node = new (&blocks_.back().nodes[used_in_block_++]) Node();
  node->type = type;
  return node;
}

void NodePool::AddBlock() {
  constexpr size_t kHuge = size_t{2} << 20;
  const size_t previous = blocks_.empty() ? 0 : blocks_.back().capacity;
  const size_t capacity = previous == 0 ? 64 : std::min(previous * 2, kHuge / sizeof(Node));
  Block block{nullptr, capacity, nullptr};
  if (capacity * sizeof(Node) * 2 > kHuge) {
    // a 2 MiB-aligned region (map twice the size, keep the aligned middle) marked for huge pages
    void* raw = mmap(nullptr, 2 * kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw != MAP_FAILED) {
      const auto start = reinterpret_cast<uintptr_t>(raw);
      const uintptr_t aligned = (start + kHuge - 1) & ~(kHuge - 1);
      if (aligned > start) munmap(raw, aligned - start);
      if (aligned + kHuge < start + 2 * kHuge) munmap(reinterpret_cast<void*>(aligned + kHuge), start + 2 * kHuge - aligned - kHuge);
      madvise(reinterpret_cast<void*>(aligned), kHuge, MADV_HUGEPAGE);
      block.mapping = reinterpret_cast<void*>(aligned);
      block.nodes = static_cast<Node*>(block.mapping);
      block.capacity = kHuge / sizeof(Node);
    }
  }
  if (!block.nodes) block.nodes = static_cast<Node*>(::operator new(capacity * sizeof(Node)));
  blocks_.push_back(block);
  used_in_block_ = 0;
}

NodePool::~NodePool() {
  for (size_t b = 0; b < blocks_.size(); ++b) {
    const size_t constructed = b + 1 == blocks_.size() ? used_in_block_ : blocks_[b].capacity;
    for (size_t k = 0; k < constructed; ++k) blocks_[b].nodes[k].~Node();
    if (blocks_[b].mapping) {
      munmap(blocks_[b].mapping, size_t{2} << 20);
    } else {
      ::operator delete(blocks_[b].nodes);
    }
  }
}

void NodePool::Release(Node* node) {
  RemoveChild(node);
  std::vector<Node*> pending{node};
  while (!pending.empty()) {
    Node* n = pending.back();
    pending.pop_back();
    for (Node* c = n->first; c; c = c->next) pending.push_back(c);
    bytes_ -= std::min(bytes_, sizeof(Node));
    free_.push_back(n);
  }
}

void NodePool::Account(size_t bytes) {
  bytes_ += bytes;
  if (bytes_ > max_bytes_) {
    throw DocumentSizeError("expanded document exceeds the size limit of " + std::to_string(max_bytes_ >> 20) +
                " MiB (runaway macro expansion?)");
  }
}

namespace {

bool IsIndentation(const std::string& s) {
  return s.find_first_not_of(" \t\n\r") == std::string::npos && std::count(s.begin(), s.end(), '\n') <= 1;
}

}  // namespace

Node* NodePool::Clone(const Node* node) {
  Node* copy = Allocate(node->type);
  copy->name = node->name;
  copy->data = node->data;
  copy->attributes = node->attributes;
  copy->file = node->file;
  copy->line = node->line;
  size_t bytes = node->name.size() + node->data.size();
  for (const auto& [k, v] : node->attributes) bytes += k.size() + v.size();
  Account(bytes);
  for (const Node* c = node->first; c; c = c->next) {
    // Indentation between siblings is half of a typical macro body and never printed. xacro's
    // comment handling skips such text (at most one newline) as if it were absent, so copies leave
    // it out; a blank line (two newlines) and the first and last child (where that handling places
    // its marker against later comment removal) are kept.
    if (c->type == Node::Type::kText && c != node->first && c != node->last && IsIndentation(c->data)) continue;
    AppendChild(copy, Clone(c));
  }
  return copy;
}

void InsertBefore(Node* parent, Node* child, Node* before) {
  if (child->parent) RemoveChild(child);
  child->parent = parent;
  if (!before) {
    child->prev = parent->last;
    child->next = nullptr;
    if (parent->last) parent->last->next = child;
    else parent->first = child;
    parent->last = child;
    return;
  }
  child->next = before;
  child->prev = before->prev;
  if (before->prev) before->prev->next = child;
  else parent->first = child;
  before->prev = child;
}

void AppendChild(Node* parent, Node* child) { InsertBefore(parent, child, nullptr); }

void RemoveChild(Node* child) {
  Node* parent = child->parent;
  if (!parent) return;
  if (child->prev) child->prev->next = child->next;
  else parent->first = child->next;
  if (child->next) child->next->prev = child->prev;
  else parent->last = child->prev;
  child->parent = child->prev = child->next = nullptr;
}

void InsertChildrenBefore(Node* from, Node* before) {
  for (Node* c = from->first; c;) {
    Node* n = c->next;
    InsertBefore(before->parent, c, before);
    c = n;
  }
}

void ReplaceNode(Node* node, Node* by, bool content_only) {
  if (by && content_only) {
    InsertChildrenBefore(by, node);
  } else if (by) {
    InsertBefore(node->parent, by, node);
  }
  RemoveChild(node);
}

namespace {

// Builds the tree from expat's callbacks. Expat is the parser Python's minidom (and so xacro)
// uses: whitespace-only text is kept (xacro's comment handling counts its newlines), attribute
// values are normalised, and error messages read the same ("mismatched tag: line 4, column 4").
struct TreeBuilder {
  // Python's recursion limit stops xacro on documents nested about this deep
  static constexpr int kMaxDepth = 1000;

  TreeBuilder(XML_Parser p, NodePool& nodes, const std::string& file_path, int file_index, Node* document)
      : parser(p), pool(nodes), path(file_path), file(file_index), current(document) {}

  XML_Parser parser;
  NodePool& pool;
  const std::string& path;
  int file;
  Node* current;
  Node* cdata = nullptr;  // the CDATA section being read
  int depth = 0;
  std::exception_ptr error;  // what stopped the parser (exceptions must not cross expat's C frames)

  Node* Add(Node::Type type) {
    Node* n = pool.Allocate(type);
    n->file = file;
    n->line = static_cast<int>(XML_GetCurrentLineNumber(parser));
    AppendChild(current, n);
    return n;
  }

  template <typename Body>
  static void Guarded(void* data, Body body) {
    auto* b = static_cast<TreeBuilder*>(data);
    if (b->error) return;
    try {
      body(*b);
    } catch (...) {
      b->error = std::current_exception();
      XML_StopParser(b->parser, XML_FALSE);
    }
  }

  static void Start(void* data, const XML_Char* name, const XML_Char** attributes) {
    Guarded(data, [&](TreeBuilder& b) {
      if (++b.depth > kMaxDepth) {
        throw Error(SourceLocation{b.path, static_cast<int>(XML_GetCurrentLineNumber(b.parser))},
                    "elements nested more than " + std::to_string(kMaxDepth) + " deep");
      }
      Node* n = b.Add(Node::Type::kElement);
      n->name = name;
      size_t bytes = n->name.size();
      for (const XML_Char** a = attributes; *a; a += 2) {
        n->attributes.emplace_back(a[0], a[1]);
        bytes += n->attributes.back().first.size() + n->attributes.back().second.size();
      }
      b.pool.Account(bytes);
      b.current = n;
    });
  }

  static void End(void* data, const XML_Char*) {
    Guarded(data, [](TreeBuilder& b) {
      --b.depth;
      b.current = b.current->parent;
    });
  }

  static void Text(void* data, const XML_Char* text, int length) {
    Guarded(data, [&](TreeBuilder& b) {
      if (b.current->type == Node::Type::kDocument) return;  // whitespace outside the root
      // expat delivers text in pieces (lines, entities): one node per run, as minidom builds it
      Node* last = b.current->last;
      Node* n = b.cdata ? b.cdata : (last && last->type == Node::Type::kText ? last : b.Add(Node::Type::kText));
      n->data.append(text, static_cast<size_t>(length));
      b.pool.Account(static_cast<size_t>(length));
    });
  }

  static void Comment(void* data, const XML_Char* text) {
    Guarded(data, [&](TreeBuilder& b) { b.Add(Node::Type::kComment)->data = text; });
  }

  static void Instruction(void* data, const XML_Char* target, const XML_Char* text) {
    Guarded(data, [&](TreeBuilder& b) {
      Node* n = b.Add(Node::Type::kProcessingInstruction);
      n->name = target;
      n->data = text;
    });
  }

  static void StartCData(void* data) {
    Guarded(data, [](TreeBuilder& b) { b.cdata = b.Add(Node::Type::kCData); });
  }

  static void EndCData(void* data) {
    Guarded(data, [](TreeBuilder& b) { b.cdata = nullptr; });
  }
};

}  // namespace

std::string PythonOsErrorText(int errno_value, const std::string& reason, const std::string& path) {
  const std::string number = errno_value ? "[Errno " + std::to_string(errno_value) + "] " : "";
  return number + reason + ": '" + path + "'";
}

Node* ParseXmlFile(const std::string& path, int file_index, NodePool& pool) {
  std::string text;
  try {
    text = ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw IoError(e.what(), path, e.errno_value);
  }

  Node* document = pool.Allocate(Node::Type::kDocument);
  document->file = file_index;
  XML_Parser parser = XML_ParserCreate(nullptr);
  TreeBuilder builder{parser, pool, path, file_index, document};
  XML_SetUserData(parser, &builder);
  XML_SetElementHandler(parser, &TreeBuilder::Start, &TreeBuilder::End);
  XML_SetCharacterDataHandler(parser, &TreeBuilder::Text);
  XML_SetCommentHandler(parser, &TreeBuilder::Comment);
  XML_SetProcessingInstructionHandler(parser, &TreeBuilder::Instruction);
  XML_SetCdataSectionHandler(parser, &TreeBuilder::StartCData, &TreeBuilder::EndCData);
  const bool ok = XML_Parse(parser, text.data(), static_cast<int>(text.size()), XML_TRUE) == XML_STATUS_OK;
  const int line = static_cast<int>(XML_GetCurrentLineNumber(parser));
  const int column = static_cast<int>(XML_GetCurrentColumnNumber(parser));
  const std::string what = ok ? "" : XML_ErrorString(XML_GetErrorCode(parser));
  XML_ParserFree(parser);
  if (builder.error) std::rethrow_exception(builder.error);
  if (!ok) {
    throw Error(SourceLocation{path, line},
                "XML parsing error: " + what + ": line " + std::to_string(line) + ", column " + std::to_string(column));
  }
  return document;
}

namespace {

void Escape(std::string& out, const std::string& s) {
  if (s.find_first_of("&<>\"") == std::string::npos) {
    out += s;
    return;
  }
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
}

bool IsBlank(const std::string& s) {
  return s.find_first_not_of(" \t\n\r\f\v") == std::string::npos;
}

void Indent(std::string& out, int depth) { out.append(static_cast<size_t>(depth) * 2, ' '); }

using AttributeList = std::vector<const std::pair<std::string, std::string>*>;

void Write(std::string& out, const Node* n, int depth, AttributeList& attrs) {
  switch (n->type) {
    case Node::Type::kText:
      Indent(out, depth);
      Escape(out, n->data);
      out += '\n';
      return;
    case Node::Type::kCData:
      out += "<![CDATA[";
      out += n->data;
      out += "]]>";
      return;
    case Node::Type::kComment:
      Indent(out, depth);
      out += "<!--";
      out += n->data;
      out += "-->\n";
      return;
    case Node::Type::kProcessingInstruction:
      Indent(out, depth);
      out += "<?" + n->name + " " + n->data + "?>\n";
      return;
    default: break;
  }
  Indent(out, depth);
  out += '<';
  out += n->name;
  attrs.clear();
  for (const auto& a : n->attributes) attrs.push_back(&a);
  std::sort(attrs.begin(), attrs.end(), [](auto* a, auto* b) { return a->first < b->first; });
  for (const auto* a : attrs) {
    out += ' ';
    out += a->first;
    out += "=\"";
    Escape(out, a->second);
    out += '"';
  }
  if (!n->first) {
    out += "/>\n";
    return;
  }
  if (n->first == n->last && n->first->type == Node::Type::kText) {
    out += '>';
    Escape(out, n->first->data);
  } else {
    out += ">\n";
    for (const Node* c = n->first; c; c = c->next) {
      if (c->type == Node::Type::kText && IsBlank(c->data)) continue;
      Write(out, c, depth + 1, attrs);
    }
    Indent(out, depth);
  }
  out += "</";
  out += n->name;
  out += ">\n";
}

}  // namespace

std::string WriteXml(const Node* document) {
  std::string out = "<?xml version=\"1.0\" ?>\n";
  out.reserve(size_t{1} << 16);
  AttributeList attrs;
  for (const Node* c = document->first; c; c = c->next) {
    if (c->type == Node::Type::kText) continue;
    Write(out, c, 0, attrs);
  }
  return out;
}

}  // namespace urdfsnap::xacro
