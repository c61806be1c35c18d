// The folder a design writes into, claimed so that a design never touches what it did not write:
//  * the folder must be new, empty, or an earlier design's: every file in it listed, with its
//    size, in that design's manifest (design_manifest.txt, written last), or what
//    scripts/plot_design.py drew from it afterwards (its four figures design_spectra, _loops,
//    _orbits and _drifts as .png, .pdf or .json, and design.html, at its top). Anything
//    else is refused before any work, naming the first file that is not the design's own;
//  * one design at a time: a lock file beside the folder (".<name>.design-lock", holding the
//    writer's pid) refuses a second design into the same folder while the first runs; a lock
//    whose process is gone is taken over;
//  * an earlier design is moved aside (".<name>.design-previous") while the new one is written,
//    and comes back untouched when the new one fails or is refused; it is removed only once the
//    new one has committed. A file the new design has yet to read (a suite record) inside it
//    would be gone before it is read: refused at the key that names it.
// The design is written at the folder's own name (not in a temporary folder renamed at the end),
// so that every path the design writes into its files (synthetic records, models, histories) is
// the path the user finds them at.
#pragma once

#include <string>
#include <vector>

namespace isolab::study {

// A file the design reads after claiming its folder, and the key that names it for messages
// ("design.yaml:4:13: suite.records[0]").
struct DesignInput {
  std::string file, key;
};

class DesignFolder {
 public:
  static constexpr const char* kManifest = "design_manifest.txt";

  // Takes the lock and checks the folder; throws InputError naming `option` (a command-line
  // option or the design file's output.directory) when the folder cannot be made, holds files
  // that are not an earlier design's, or another design is writing into it, and naming an
  // input's key when the input lies inside an earlier design that would be moved aside. Changes
  // nothing then.
  DesignFolder(std::string folder, std::string option, const std::vector<DesignInput>& inputs);
  // Without Commit(): removes what this design wrote and puts the earlier design back.
  ~DesignFolder();
  DesignFolder(const DesignFolder&) = delete;
  DesignFolder& operator=(const DesignFolder&) = delete;

  const std::string& path() const { return folder_; }

  // Writes the manifest of everything now in the folder and drops the earlier design. Throws
  // ResourceError when the manifest cannot be written (the design is then rolled back).
  void Commit();

 private:
  void RollBack() noexcept;

  std::string folder_, option_;
  std::string target_;  // absolute
  std::string lock_, previous_;
  std::vector<std::string> created_parents_;  // folders made above it, deepest first
  bool existed_ = false;        // the folder was there (empty or an earlier design's) before
  bool had_earlier_ = false;    // an earlier design was moved to previous_
  bool owns_contents_ = false;  // everything in the folder is this design's
  bool committed_ = false;
};

}  // namespace isolab::study
