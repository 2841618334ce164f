// OutputPlan: paths made canonical once (their folders cached), files and inputs looked up by
// canonical path and by inode, sequences and folders compared with every other entry; the names
// of two sequences compared as two small automata run side by side (NumberedNamesMeet).
#include "common/output_plan.h"

#include <sys/stat.h>

#include <filesystem>
#include <set>
#include <system_error>

#include "common/atomic_file.h"
#include "common/error.h"

namespace urdfsnap {

namespace fs = std::filesystem;

namespace {

// One form of names as a list of tokens: a literal character, or kDigits (one or more digits).
constexpr int kDigits = -1;

std::vector<int> Tokens(std::string_view prefix, std::string_view suffix, bool numbered) {
  std::vector<int> tokens;
  for (const char ch : prefix) tokens.push_back(static_cast<unsigned char>(ch));
  if (numbered) tokens.push_back(kDigits);
  for (const char ch : suffix) tokens.push_back(static_cast<unsigned char>(ch));
  return tokens;
}

bool IsDigit(int token) { return token >= '0' && token <= '9'; }

// "x" is inside folder "f" when it is "f/..." (both canonical).
bool IsInside(const std::string& path, const std::string& folder) {
  return path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
         (path[folder.size()] == '/' || folder == "/");
}

std::string Quoted(const std::string& role, const std::string& path) { return role + " '" + path + "'"; }

// `path` with every symbolic link resolved; as named when it cannot be looked into.
std::string Resolved(const fs::path& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(path, error);
  return error ? path.string() : resolved.string();
}

}  // namespace

bool NumberedNamesMeet(std::string_view prefix_a, std::string_view suffix_a, std::string_view prefix_b,
                       std::string_view suffix_b, bool numbered_b) {
  const std::vector<int> a = Tokens(prefix_a, suffix_a, true), b = Tokens(prefix_b, suffix_b, numbered_b);
  const std::size_t width = b.size() + 1;
  std::vector<bool> seen((a.size() + 1) * width, false);
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, 0}};
  // the states after one more character read by both: a digit token may read another digit
  const auto next = [](const std::vector<int>& tokens, std::size_t i, int ch, std::vector<std::size_t>& out) {
    out.clear();
    if (i == tokens.size()) return;
    if (tokens[i] == kDigits) {
      if (IsDigit(ch)) out = {i, i + 1};
    } else if (tokens[i] == ch) {
      out = {i + 1};
    }
  };
  std::vector<std::size_t> to_a, to_b;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (i == a.size() && j == b.size()) return true;
    if (i == a.size() || j == b.size() || seen[i * width + j]) continue;
    seen[i * width + j] = true;
    // the character both read: a literal one's, or any digit when both read digits
    const int ch = a[i] != kDigits ? a[i] : b[j] != kDigits ? b[j] : '0';
    next(a, i, ch, to_a);
    next(b, j, ch, to_b);
    for (const std::size_t x : to_a) {
      for (const std::size_t y : to_b) stack.emplace_back(x, y);
    }
  }
  return false;
}

struct OutputPlan::Entry {
  enum class Kind { kFile, kSequence, kFolder, kInput };
  Kind kind;
  std::string path, role;   // as given, for messages
  std::string canonical;    // the canonical path; for a sequence its prefix
  std::string suffix;       // of a sequence
  bool make_folders = true;  // missing folders above it are made
  bool exists = false;      // a file or folder is there (inode set)
  dev_t device = 0;
  ino_t inode = 0;
};

OutputPlan::OutputPlan() = default;
OutputPlan::~OutputPlan() = default;

std::string OutputPlan::Canonical(const std::string& path, bool follow_leaf) {
  std::error_code error;
  const fs::path absolute = fs::absolute(fs::path(path), error).lexically_normal();
  if (follow_leaf && fs::is_symlink(fs::symlink_status(absolute, error))) return Resolved(absolute);
  // the folder part resolved once per folder; "a/b/" names the folder b
  const fs::path folder = absolute.parent_path(), name = absolute.filename();
  if (name.empty() && folder != absolute) return Canonical(folder.string(), follow_leaf);
  if (name.empty()) return absolute.string();  // the root
  auto [at, added] = canonical_folders_.emplace(folder.string(), "");
  if (added) at->second = Resolved(folder);
  if (name == "." || name == "..") return Resolved(absolute);
  return (fs::path(at->second) / name).string();
}

void OutputPlan::AddFile(const std::string& path, const std::string& role, bool make_folders) {
  entries_.push_back({Entry::Kind::kFile, path, role, Canonical(path, true), "", make_folders});
}

void OutputPlan::AddSequence(const std::string& pattern, const std::string& prefix, const std::string& suffix,
                             const std::string& role) {
  // the folder part of the prefix resolved; the number may stand in the file name or a folder's
  const std::size_t slash = prefix.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : prefix.substr(0, slash + 1);
  std::string canonical = Canonical(folder + ".", false);
  if (canonical != "/") canonical += "/";
  canonical += prefix.substr(slash == std::string::npos ? 0 : slash + 1);
  entries_.push_back({Entry::Kind::kSequence, pattern, role, canonical, suffix});
}

void OutputPlan::AddFolder(const std::string& path, const std::string& role) {
  entries_.push_back({Entry::Kind::kFolder, path, role, Canonical(path, true), ""});
}

void OutputPlan::AddInput(const std::string& path, const std::string& role) {
  if (path.empty()) return;
  entries_.push_back({Entry::Kind::kInput, path, role, Canonical(path, true), ""});
}

void OutputPlan::Check(const Entry& entry) {
  std::error_code error;
  if (entry.kind == Entry::Kind::kFile && entry.exists && fs::is_directory(entry.canonical, error)) {
    throw Error(entry.path + ": cannot write: " + std::make_error_code(std::errc::is_a_directory).message());
  }
  if (entry.kind == Entry::Kind::kFolder && entry.exists && !fs::is_directory(entry.canonical, error)) {
    throw Error(Quoted(entry.role, entry.path) + ": exists and is not a folder");
  }
}

void OutputPlan::Prepare() {
  for (Entry& entry : entries_) {
    struct stat status {};
    if (entry.kind != Entry::Kind::kSequence && ::stat(entry.canonical.c_str(), &status) == 0) {
      entry.exists = true;
      entry.device = status.st_dev;
      entry.inode = status.st_ino;
    }
  }
  // files and inputs by canonical path and by inode: inputs first, so each output meets them all
  std::map<std::string, const Entry*> by_path;
  std::map<std::pair<dev_t, ino_t>, const Entry*> by_inode;
  std::vector<const Entry*> spread;  // sequences and folders, compared with every entry
  const auto clash = [](const Entry& output, const Entry& other, const std::string& how) {
    return Error(Quoted(output.role, output.path) + ": " + how + " " + Quoted(other.role, other.path));
  };
  for (const bool inputs : {true, false}) {
    for (const Entry& entry : entries_) {
      if ((entry.kind == Entry::Kind::kInput) != inputs) continue;
      if (entry.kind == Entry::Kind::kSequence || entry.kind == Entry::Kind::kFolder) {
        spread.push_back(&entry);
        continue;
      }
      const auto [at, added] = by_path.emplace(entry.canonical, &entry);
      if (!added && !inputs) throw clash(entry, *at->second, "the same file as");
      if (!entry.exists || entry.kind == Entry::Kind::kFolder) continue;
      const auto [same, new_inode] = by_inode.emplace(std::pair{entry.device, entry.inode}, &entry);
      if (!new_inode && !inputs) throw clash(entry, *same->second, "the same file as");
    }
  }
  for (const Entry* wide : spread) {
    for (const Entry& other : entries_) {
      if (&other == wide || (other.kind == Entry::Kind::kInput && wide->kind == Entry::Kind::kInput)) continue;
      if (wide->kind == Entry::Kind::kFolder) {
        if (other.canonical == wide->canonical) throw clash(*wide, other, "the same file as");
        if (IsInside(other.canonical, wide->canonical)) throw clash(*wide, other, "holds");
        if (other.kind == Entry::Kind::kFolder && IsInside(wide->canonical, other.canonical)) {
          throw clash(*wide, other, "is inside");
        }
        continue;
      }
      if (other.kind == Entry::Kind::kFolder) continue;  // met from the folder's side
      const bool numbered = other.kind == Entry::Kind::kSequence;
      if (numbered && &other < wide) continue;  // each pair of sequences once
      if (NumberedNamesMeet(wide->canonical, wide->suffix, other.canonical, other.suffix, numbered)) {
        throw clash(*wide, other, numbered ? "may name the same files as" : "may name the same file as");
      }
    }
  }
  for (const Entry& entry : entries_) Check(entry);
  // the folders made where asked, and one file tried in each folder
  std::set<std::string> tried;
  for (const Entry& entry : entries_) {
    if (entry.kind == Entry::Kind::kInput) continue;
    const bool numbered = entry.kind == Entry::Kind::kSequence;
    if (entry.make_folders) folders_.MakeParents(numbered ? entry.canonical + "0" + entry.suffix : entry.path);
    if (entry.kind == Entry::Kind::kFolder) continue;
    if (tried.insert(fs::path(entry.canonical).parent_path().string()).second) {
      AtomicFile probe(numbered ? entry.canonical + "0" + entry.suffix : entry.path);  // made and removed
    }
  }
}

AtomicFile& OutputPlan::Open(const std::string& path) {
  staged_.push_back(std::make_unique<AtomicFile>(path));
  return *staged_.back();
}

void OutputPlan::Write(const std::string& path, std::string_view bytes) {
  AtomicFile& file = Open(path);
  file.Write(bytes);
  file.Close();
}

void OutputPlan::Commit() {
  for (const std::unique_ptr<AtomicFile>& file : staged_) file->Commit();
  staged_.clear();
  folders_.Keep();
}

}  // namespace urdfsnap
