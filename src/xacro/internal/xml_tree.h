// The document tree xacro edits in place (as xacro edits its minidom tree): elements with ordered
// attributes, text, CDATA and comments, linked as siblings, each remembering the file and line it
// came from. Nodes live in a NodePool that bounds the size of the expanded document.
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace urdfsnap::xacro {

struct Node {
  enum class Type { kDocument, kElement, kText, kCData, kComment, kProcessingInstruction };
  Type type = Type::kElement;
  std::string name;  // element tag; processing instruction target
  std::string data;  // text, CDATA, comment or processing instruction content
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order
  Node* parent = nullptr;
  Node* first = nullptr;
  Node* last = nullptr;
  Node* prev = nullptr;
  Node* next = nullptr;
  int file = -1;  // index into the processor's file names
  int line = 0;

  // The attribute's value, or nullptr.
  const std::string* Attribute(const std::string& key) const;
  // Sets (or adds at the end) an attribute.
  void SetAttribute(const std::string& key, std::string value);
  // Removes an attribute if present.
  void RemoveAttribute(const std::string& key);
  // The first child element (text and comments skipped), or nullptr; likewise the next sibling.
  Node* FirstChildElement() const;
  Node* NextSiblingElement() const;
};

// Owns every node of one run and counts their size; Allocate throws DocumentSizeError once the
// expanded document would exceed `max_bytes`.
class NodePool {
 public:
  explicit NodePool(size_t max_bytes) : max_bytes_(max_bytes) {}
  ~NodePool();
  NodePool(const NodePool&) = delete;
  NodePool& operator=(const NodePool&) = delete;

  Node* Allocate(Node::Type type);
  // A deep copy of `node` (unlinked).
  Node* Clone(const Node* node);
  // Counts `bytes` more of document content (attribute values, text).
  void Account(size_t bytes);
  // Unlinks `node` and gives it and its subtree back for reuse; nothing may refer to them.
  void Release(Node* node);

 private:
  // Nodes are constructed in place in blocks that grow from 64 nodes (small documents touch little
  // memory) to 2 MiB huge-page regions (large documents take few page faults, which dominate the
  // cost of building big trees).
  struct Block {
    Node* nodes;
    size_t capacity;
    void* mapping;  // the mmap'd region of a huge-page block, else nullptr
  };
  void AddBlock();

  std::vector<Block> blocks_;
  size_t used_in_block_ = 0;
  std::vector<Node*> free_;  // released nodes, reused first (their strings keep their capacity)
  size_t bytes_ = 0;
  size_t max_bytes_;
};

// Tree editing in the manner of the DOM.
void AppendChild(Node* parent, Node* child);
void InsertBefore(Node* parent, Node* child, Node* before);  // before == nullptr appends
void RemoveChild(Node* child);
// Moves the children of `from` in front of `before` (in before's parent).
void InsertChildrenBefore(Node* from, Node* before);
// Replaces `node` by `by` (or by the children of `by` when `content_only`); `by` may be nullptr
// to just remove `node`.
void ReplaceNode(Node* node, Node* by, bool content_only);

// A file that cannot be read; what() is "No such file or directory: PATH" (strerror: path).
class IoError : public std::runtime_error {
 public:
  // what() is "REASON: PATH" ("No such file or directory: robot.xacro").
  IoError(const std::string& reason, const std::string& path, int errno_value)
      : std::runtime_error(reason + ": " + path), reason(reason), errno_value(errno_value) {}
  std::string reason;
  int errno_value;  // 0 for urdfsnap's file size limit
};

// Python's text for an OSError: "[Errno 2] No such file or directory: 'x.yaml'"; just
// "REASON: 'PATH'" without an errno (urdfsnap's size limit).
std::string PythonOsErrorText(int errno_value, const std::string& reason, const std::string& path);

// The nodes and text of all documents grew past NodePool's limit; the processor adds where.
class DocumentSizeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses the XML file `path` into a document node (comments and whitespace kept, XML declaration
// and DOCTYPE dropped). Throws urdfsnap::Error "XML parsing error: mismatched tag: line 4,
// column 4" for malformed XML and IoError when it cannot be read. `file_index` is stored on every
// node.
Node* ParseXmlFile(const std::string& path, int file_index, NodePool& pool);

// Writes the document as xacro's pretty printer does: `<?xml version="1.0" ?>`, two-space
// indentation, attributes sorted by name, an element with one text child on one line,
// whitespace-only text between elements dropped.
std::string WriteXml(const Node* document);

}  // namespace urdfsnap::xacro
