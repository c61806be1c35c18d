#include "isolab/study/design_workflow.h"

#include <memory>

#include "isolab/core/hardware_threads.h"
#include "isolab/study/design_folder.h"
#include "isolab/study/design_report.h"
#include "isolab/study/scheduler.h"

namespace isolab::study {

DesignRun RunDesignIntoFolder(const model::DesignFile& design, const DesignFolderOptions& options,
                              const std::function<void(const std::string&)>& progress,
                              const std::function<void(const std::string& folder)>& finish) {
  const std::unique_ptr<DesignFolder> claimed =
      ClaimDesignFolder(options.output, design, options.output_option);
  DesignRun run;
  run.folder = claimed->path();
  const std::unique_ptr<Scheduler> scheduler = MakeLocalScheduler(ThreadsOrHardware(options.jobs));
  run.scheduler = scheduler->Describe();
  run.outcome = RunDesign(design, run.folder, options.version, *scheduler, progress);
  if (run.outcome.failed > 0) return run;  // the claim rolls back
  WriteDesignFiles(design, run.outcome, run.folder, options.figures);
  if (finish) finish(run.folder);
  claimed->Commit();
  run.committed = true;
  return run;
}

}  // namespace isolab::study
