// The xacro document tree: parsing with tinyxml2 (keeping line numbers), in-place editing, and
// xacro's pretty printer.
#include "xacro/xml_tree.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "common/error.h"

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
  if (used_in_block_ == kBlockNodes) {
    blocks_.push_back(std::make_unique<Node[]>(kBlockNodes));
    used_in_block_ = 0;
  }
  Node* node = &blocks_.back()[used_in_block_++];
  node->type = type;
  return node;
}

void NodePool::Account(size_t bytes) {
  bytes_ += bytes;
  if (bytes_ > max_bytes_) {
    throw Error("expanded document exceeds the size limit of " + std::to_string(max_bytes_ >> 20) +
                " MiB (runaway macro expansion?)");
  }
}

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
  for (const Node* c = node->first; c; c = c->next) AppendChild(copy, Clone(c));
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

// XML attribute-value normalisation (what expat does): literal TAB/CR/LF become spaces
std::string NormalizeAttribute(const char* value) {
  std::string v = value;
  for (char& c : v) {
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  }
  return v;
}

void Convert(const tinyxml2::XMLNode* from, Node* to, int file, NodePool& pool) {
  for (const tinyxml2::XMLNode* c = from->FirstChild(); c; c = c->NextSibling()) {
    Node* n = nullptr;
    if (const auto* e = c->ToElement()) {
      n = pool.Allocate(Node::Type::kElement);
      n->name = e->Name();
      size_t bytes = n->name.size();
      for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
        n->attributes.emplace_back(a->Name(), NormalizeAttribute(a->Value()));
        bytes += n->attributes.back().first.size() + n->attributes.back().second.size();
      }
      pool.Account(bytes);
      Convert(c, n, file, pool);
    } else if (const auto* t = c->ToText()) {
      n = pool.Allocate(t->CData() ? Node::Type::kCData : Node::Type::kText);
      n->data = t->Value();
      pool.Account(n->data.size());
    } else if (const auto* k = c->ToComment()) {
      n = pool.Allocate(Node::Type::kComment);
      n->data = k->Value();
      pool.Account(n->data.size());
    } else {
      continue;  // XML declaration, DOCTYPE
    }
    n->file = file;
    n->line = c->GetLineNum();
    AppendChild(to, n);
  }
}

}  // namespace

Node* ParseXmlFile(const std::string& path, int file_index, NodePool& pool) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (!in) throw IoError(std::string(std::strerror(errno)) + ": " + path);
  std::string text;
  char chunk[65536];
  for (size_t n; (n = std::fread(chunk, 1, sizeof chunk, in)) > 0;) text.append(chunk, n);
  std::fclose(in);
  tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    std::string what = doc.ErrorStr() ? doc.ErrorStr() : "malformed XML";
    throw Error(SourceLocation{path, doc.ErrorLineNum()}, "XML parsing error: " + what);
  }
  if (!doc.RootElement()) throw Error(SourceLocation{path, 0}, "XML parsing error: no element found");
  Node* document = pool.Allocate(Node::Type::kDocument);
  document->file = file_index;
  Convert(&doc, document, file_index, pool);
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

void Write(std::string& out, const Node* n, int depth) {
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
    default: break;
  }
  Indent(out, depth);
  out += '<';
  out += n->name;
  std::vector<const std::pair<std::string, std::string>*> attrs;
  attrs.reserve(n->attributes.size());
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
      Write(out, c, depth + 1);
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
  for (const Node* c = document->first; c; c = c->next) {
    if (c->type == Node::Type::kText) continue;
    Write(out, c, 0);
  }
  return out;
}

}  // namespace urdfsnap::xacro
