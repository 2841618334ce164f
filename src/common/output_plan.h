// The files a command will write, planned before any work is done, so that a run either writes
// all of them or leaves every folder as it found it:
//   - no two outputs are the same file, nor an output the same file as an input: compared by the
//     path with every symbolic link resolved, and by device and inode for files that exist (hard
//     links); a numbered sequence ("frames/%05d.png") against every name it can take; a folder
//     replaced as a whole against everything inside it;
//   - an output is no existing folder, and no file stands where its folders should be; the
//     missing folders are made, and removed again when the run fails;
//   - the bytes go to temporary files beside their outputs, renamed into place only by Commit,
//     once everything has been written; a plan destroyed before that removes them.
// Every error is urdfsnap::Error naming the outputs by the option that gave them.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/atomic_file.h"
#include "common/created_folders.h"

namespace urdfsnap {

class OutputPlan {
 public:
  OutputPlan();
  // Removes the temporary files written and the folders made, unless Commit ran.
  ~OutputPlan();
  OutputPlan(const OutputPlan&) = delete;
  OutputPlan& operator=(const OutputPlan&) = delete;

  // An output file; `role` names it in messages ("-o", "--depth", "the link names of --labels").
  // Without `make_folders` a missing folder above it is an error ("PATH: cannot write: ...").
  void AddFile(const std::string& path, const std::string& role, bool make_folders = true);
  // Numbered output files `pattern` (as given, for messages): `prefix`, a frame number of one or
  // more digits, then `suffix` ("frames/" and ".png" for frames/%05d.png). The files are written
  // by their own writer.
  void AddSequence(const std::string& pattern, const std::string& prefix, const std::string& suffix,
                   const std::string& role);
  // A folder written as a whole (replaced, or filled with files whose names are not known yet):
  // no other output, and no input, may be in it.
  void AddFolder(const std::string& path, const std::string& role);
  // A file the command reads ("the model"): no output may be it. A path that is not there (yet)
  // is left out.
  void AddInput(const std::string& path, const std::string& role);

  // Checks the outputs against each other and against the inputs, then makes the folders they
  // need and checks that a file can be made in each. Throws urdfsnap::Error
  // "ROLE 'PATH': the same file as ROLE 'PATH'" (or "may name the same file(s) as", "holds",
  // "is inside"), "ROLE 'PATH': exists and is not a folder" (a folder output), "PATH: cannot
  // write: <reason>" (an existing folder, a missing one or a file in the way, no permission),
  // "PATH: cannot make the folder 'DIR': <reason>".
  void Prepare();

  // A new temporary file beside `path` (an output of this plan), written by the caller piece by
  // piece; it replaces `path` at Commit. Throws urdfsnap::Error "PATH: cannot write: ...".
  AtomicFile& Open(const std::string& path);
  // Open, the whole of `bytes`, and the file closed (so that thousands can wait for Commit).
  void Write(const std::string& path, std::string_view bytes);
  void Write(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    Write(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  }
  // Moves every written file into place and keeps the folders made. Throws urdfsnap::Error when
  // a rename fails (the files not yet moved are then removed).
  void Commit();

 private:
  struct Entry;
  void Check(const Entry& entry);
  std::string Canonical(const std::string& path, bool follow_leaf);

  std::vector<Entry> entries_;
  std::map<std::string, std::string> canonical_folders_;  // a cache: suites plan thousands of files
  CreatedFolders folders_;                            // removed after the files below
  std::vector<std::unique_ptr<AtomicFile>> staged_;   // written, closed, not yet renamed
};

// Whether a name of the form prefix_a + DIGITS + suffix_a can equal one of the form prefix_b +
// DIGITS + suffix_b (DIGITS one or more decimal digits; with `numbered_b` false the second form
// is the one name prefix_b + suffix_b, no digits between).
bool NumberedNamesMeet(std::string_view prefix_a, std::string_view suffix_a, std::string_view prefix_b,
                       std::string_view suffix_b, bool numbered_b);

}  // namespace urdfsnap
