#pragma once
// The model's commands (built with LibTorch only):
//   graspecmf train --config FILE --data DIR --out RUN [--threads N]
//   graspecmf export-model --model RUN --out DIR
//   graspecmf sample [--model RUN] (--mesh FILE [--scale S] | --points FILE | --acronym FILE.h5
//                    [--mesh-root DIR]) --num 100 [--solver rkmk4 --steps 20 --guidance 2.0
//                    --seed S] [--threads N] --out grasps.h5
//   graspecmf evaluate [--model RUN] (--data DIR [--split test] | --acronym FILE.h5 [--mesh-root
//   DIR])
//                      [--num N] [--seed S] [--threads N] [--out report.json] [--markdown FILE]

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers train, export-model, sample and evaluate on app (sample and evaluate default to the
// bundled model).
void add_model_commands(CLI::App& app);

}  // namespace graspecmf::apps
