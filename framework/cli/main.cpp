// The `antipode` command: runs, validates and inspects behaviour trees and plugins.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

#include "antipode/config.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "bench_commands.hpp"
#include "commands.hpp"
#include "view_page.hpp"

namespace {

// "antipode bench: no subcommand 'foo' (did you mean ...?); subcommands: isolation, ..." when
// a word names no command, "antipode bench needs a subcommand: ..." when none is given, else
// "" (CLI11 says only that the word was not expected, or that a subcommand is required).
std::string unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  const CLI::App* parent = &app;
  std::string path = "antipode";
  const auto names_of = [](const CLI::App* command) {
    std::vector<std::string> names;
    for (const CLI::App* sub : command->get_subcommands({})) names.push_back(sub->get_name());
    return names;
  };
  const auto joined = [](const std::vector<std::string>& names) {
    std::string list;
    for (const auto& name : names) list.append(list.empty() ? "" : ", ").append(name);
    return list;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    const std::vector<std::string> names = names_of(parent);
    if (word.empty() || word[0] == '-' || names.empty()) return "";
    const std::string kind = parent == &app ? "command" : "subcommand";
    if (std::find(names.begin(), names.end(), word) == names.end()) {
      std::string message = path;
      message.append(": no ").append(kind).append(" '").append(word).append("'");
      message.append(antipode::did_you_mean(word, names)).append("; ").append(kind);
      return message.append("s: ").append(joined(names));
    }
    parent = parent->get_subcommand(word);
    path += " " + word;
  }
  if (parent != &app && parent->get_require_subcommand_min() > 0)
    return path + " needs a subcommand: " + joined(names_of(parent));
  return "";
}

constexpr const char* kExamples = R"(Examples:
  antipode run trees/pick_isolated.yaml
  antipode run trees/detect.yaml --set cloud_file=../shared/data/clouds/krylon.pcd \
      --set sampler.samples=500 --seed 3 --trace run.jsonl
  antipode validate trees/detect.yaml
  antipode detect ../shared/data/clouds/table_mug.pcd --out grasps.json --image grasps.png
  antipode scene scenes/pile_procedural.yaml --image scene.png
  antipode bench isolation --objects ../shared/data/objects/ycb --jobs 2 --report iso.json
  antipode bench clutter --runs 10 --jobs 2 --report clutter.json
  antipode bench clutter --shard 2/4 --report shard2.json
  antipode bench merge shard*.json --report clutter.json
  antipode report iso.json clutter.json --out results.md --notes notes.md
  antipode view ../shared/data/clouds/table_mug.pcd grasps.json --out view.html
  antipode view clutter.json --selections sel --pictures pics --out run.html
  antipode bench reach --ik-poses 10000 --scenes 100 --report reach.json
  antipode train --out my.model --dataset examples.data
  antipode eval-classifier --model my.model --report eval.json
  antipode plugins
  antipode plugins --check build/plugins/libantipode_my_sampler.so
  antipode nodes
  antipode nodes CollectExamples

Exit codes: 0 success, 1 the tree returned FAILURE, 2 invalid input (command line, tree,
parameters, data file), 3 internal error. See docs/cli.md.)";

struct Commands {
  antipode::cli::RunOptions run;
  antipode::cli::DetectOptions detect;
  antipode::cli::SceneOptions scene;
  antipode::cli::TrainOptions train;
  antipode::evaluation::OutcomeDataOptions outcomes;
  antipode::cli::EvalOptions eval;
  antipode::evaluation::IsolationBenchOptions isolation;
  antipode::evaluation::ReachBenchOptions reach;
  antipode::evaluation::ClutterBenchOptions clutter;
  antipode::evaluation::BenchMergeOptions merge;
  antipode::evaluation::ReportOptions report;
  antipode::cli::ViewOptions view;
  antipode::cli::RobotCheckOptions robot_check;
  std::vector<std::string> validate_paths;
  std::string node_type;        ///< `antipode nodes [TYPE]`
  std::string check_library;    ///< `antipode plugins --check LIB`
  std::string index_directory;  ///< `antipode plugins --write-index DIR`
};

// A seed: a whole number in 0 .. 2^64-1, written in digits (CLI11 alone takes "-1" as
// 2^64-1 and "" as 0).
const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
      const bool digits = !text.empty() && text.size() <= 20 &&
                          text.find_first_not_of("0123456789") == std::string::npos;
      if (digits && (text.size() < 20 || text <= "18446744073709551615")) return "";
      return "a seed is a whole number from 0 to 18446744073709551615, got '" + text + "'";
    },
    "SEED");

// --set, --seed and -v: the options of every command that runs a tree.
void add_tree_run_options(CLI::App& command, antipode::evaluation::TreeRunSettings& settings) {
  command.add_option("--set", settings.set,
                     "Override: component.parameter=value, or key=value for a blackboard entry "
                     "of the main tree (repeatable)");
  command.add_option("--seed", settings.seed, "Seed of every random stream (default 0)")
      ->check(kSeed);
  command.add_flag("-v,--verbose", settings.verbose, "Print every node's status changes");
}

void add_run(CLI::App& app, Commands& commands) {
  auto& options = commands.run;
  CLI::App* run = app.add_subcommand("run", "Run a behaviour tree");
  run->add_option("tree", options.tree_path, "YAML tree file")->required();
  add_tree_run_options(*run, options.settings);
  run->add_option("--trace", options.trace_path, "Write every status change as JSON lines");
  run->add_flag_callback(
         "-q,--quiet", [&options] { options.settings.verbose = false; },
         "No per-node trace on the console (the default; -v prints it)")
      ->excludes("--verbose");
}

void add_detect(CLI::App& app, Commands& commands) {
  auto& options = commands.detect;
  CLI::App* detect = app.add_subcommand("detect", "Detect grasps in a PCD or PLY cloud");
  detect->add_option("cloud", options.cloud_path, "PCD or PLY file")->required();
  detect->add_option("--tree", options.tree_path, "Detection tree")->capture_default_str();
  detect->add_option("--out", options.out_path, "Write the grasps as JSON");
  detect->add_option("--image", options.image_path, "Draw the cloud and grasps into a PNG");
  detect
      ->add_option("--camera-pose", options.camera_pose,
                   "The camera's pose in the robot's frame: 'x y z qw qx qy qz' or an extrinsics "
                   "YAML file; grasps are then given in that frame")
      ->type_name("POSE|FILE");
  detect->add_option(
      "--frame", options.frame,
      "The name of the output frame (default: base with --camera-pose, else sensor)");
  detect
      ->add_option("--top", options.top, "Select and rank at most N grasps, as a robot tries them")
      ->check(CLI::Range(1, 1000000));
  detect
      ->add_option("--per-object", options.per_object,
                   "Select at most N grasps per object (with or without --top)")
      ->check(CLI::Range(1, 1000000));
  detect
      ->add_option("--workspace", options.workspace,
                   "Only points in this box: XMIN YMIN ZMIN XMAX YMAX ZMAX (m, output frame)")
      ->expected(6);
  detect->add_flag("--explain", options.explain,
                   "Print the support and objects found, the hands each stage kept per object "
                   "and how many of the grasps lie on objects (the selected ones with --top or "
                   "--per-object, else the 12 best)");
  detect->add_flag("--rejected", options.rejected,
                   "Also write to --out the hands a stage dropped, each with its reason "
                   "(antipode view colours and filters them)");
  add_tree_run_options(*detect, options.settings);
}

void add_scene(CLI::App& app, Commands& commands) {
  auto& options = commands.scene;
  CLI::App* scene = app.add_subcommand("scene", "Draw a simulated scene (and grasps) into a PNG");
  scene->add_option("scene", options.scene_path, "Scene YAML file")->required();
  scene->add_option("--image", options.image_path, "Output PNG")->capture_default_str();
  scene->add_option("--grasps", options.grasps_path, "Grasps JSON to draw (from --out)");
  scene->add_option("--tree", options.tree_path, "Scene tree")->capture_default_str();
  add_tree_run_options(*scene, options.settings);
}

void add_train(CLI::App& app, Commands& commands) {
  auto& options = commands.train;
  CLI::App* train = app.add_subcommand(
      "train", "Train the HOG + SVM grasp classifier in the simulated cell (trees/train.yaml)");
  train->add_option("--out", options.model_path, "Model file to write")->capture_default_str();
  train->add_option("--dataset", options.dataset_path, "Also keep the examples in this file");
  train->add_flag("--overwrite", options.overwrite,
                  "Replace a shipped model (models/); without it train refuses to");
  train->add_option("--tree", options.tree_path, "Training tree")->capture_default_str();
  add_tree_run_options(*train, options.settings);
}

void add_outcomes(CLI::App& app, Commands& commands) {
  auto& o = commands.outcomes;
  CLI::App* outcomes = app.add_subcommand(
      "outcomes",
      "Try grasps in simulated training scenes and keep what held (trees/outcomes.yaml)");
  outcomes->add_option("--out", o.out_dir, "Folder of the trial files (one pair per scene)")
      ->required();
  outcomes->add_option("--scenes", o.scenes, "Scenes to run")->capture_default_str();
  outcomes->add_option("--first-seed", o.first_seed, "Seed of the first scene")
      ->capture_default_str();
  outcomes->add_option("--shard", o.shard,
                       "i/n: run every n-th scene from the i-th; auto: the scheduler's (a Slurm "
                       "array task, a Kubernetes Indexed Job pod)");
  outcomes->add_option("--jobs", o.jobs, "Processes")->capture_default_str();
  outcomes->add_option("--tree", o.tree_path, "Outcome tree")->capture_default_str();
  outcomes->add_option("--set", o.set, "key=value or component.key=value (repeatable)");
}

void add_eval(CLI::App& app, Commands& commands) {
  auto& options = commands.eval;
  CLI::App* eval = app.add_subcommand(
      "eval-classifier",
      "Measure a classifier model on novel objects (trees/eval_classifier.yaml)");
  eval->add_option("--model", options.model_path, "Model file")->capture_default_str();
  eval->add_option("--report", options.report_path, "Write the numbers as JSON");
  eval->add_option("--tree", options.tree_path, "Evaluation tree")->capture_default_str();
  add_tree_run_options(*eval, options.settings);
}

void add_bench_reach(CLI::App& bench, antipode::evaluation::ReachBenchOptions& o) {
  CLI::App* reach =
      bench.add_subcommand("reach", "Inverse kinematics of the arm (TRAC-IK's protocol)");
  reach->add_option("--robot", o.robot_path, "Robot file (robots/*/*.yaml)")->capture_default_str();
  reach->add_option("--base", o.base_link, "Base link of the IK chain (default: the URDF's root)");
  reach->add_option("--tip", o.tip_link, "Tip link of the IK chain (default: the hand's link)");
  reach->add_option("--ik-poses", o.ik_poses, "Random reachable poses")->capture_default_str();
  reach->add_option("--seed", o.seed, "Seed of the poses")->capture_default_str()->check(kSeed);
  reach->add_option("--solvers", o.solvers, "Any of dls,kdl,dls_kdl")->delimiter(',');
  reach->add_option("--timeout-ms", o.timeout_ms, "Time limit per pose")->capture_default_str();
  reach->add_option("--tolerance", o.tolerance, "m and rad per component")->capture_default_str();
  reach->add_option("--scenes", o.scenes, "Clutter scenes to plan in (0: none)")
      ->capture_default_str();
  reach->add_option("--scene", o.scene_file, "Scene file of the clutter scenes")
      ->capture_default_str();
  reach->add_option("--views", o.views, "The cell's views to capture")->delimiter(',');
  reach->add_option("--tree", o.scene_tree, "Tree whose components detect and plan")
      ->capture_default_str();
  reach->add_option("--set", o.set, "component.key=value for the scene tree (repeatable)");
  reach->add_option("--problems", o.problems, "Problems per planning scene (0: none)")
      ->capture_default_str();
  reach->add_option("--problem-scenes", o.problem_scenes, "Planning scene files")->delimiter(',');
  reach->add_flag("--side-by-side", o.side_by_side,
                  "Plan every problem also with FCL alone, segments in order "
                  "(planner.collision=exact, planner.segment_order=in_order)");
  reach->add_option("--report", o.report_path, "Write the report as JSON");
}

void add_bench_clutter(CLI::App& bench, antipode::evaluation::ClutterBenchOptions& o) {
  CLI::App* clutter = bench.add_subcommand(
      "clutter", "The paper's dense-clutter experiment: seeded clear-the-box runs");
  clutter
      ->add_option("--objects", o.objects,
                   "'procedural' (the scene's random shapes) or a mesh folder")
      ->capture_default_str();
  clutter->add_option("--runs", o.runs, "Clear-the-box runs")->capture_default_str();
  clutter->add_option("--protocol", o.protocol, "paper (the default), vgn-pile or vgn-packed")
      ->capture_default_str();
  clutter
      ->add_option("--objects-per-run", o.objects_per_run,
                   "Objects dumped into the box (default: the protocol's, 10 or 5)")
      ->check(CLI::Range(1, 100));
  clutter->add_option("--seed", o.seed, "Cell seed of run 0 (run i: seed + i)")
      ->capture_default_str()
      ->check(kSeed);
  clutter
      ->add_option("--replicates", o.replicates,
                   "Run each seed this many times: the first as the tree is, the others with "
                   "0.1 mm of execution noise drawn anew (the spread between draws)")
      ->capture_default_str();
  clutter->add_option("--jobs", o.jobs, "Processes (the same results for any number)")
      ->capture_default_str();
  clutter->add_option("--report", o.report_path, "Write the report as JSON");
  clutter->add_option("--tree", o.tree_path,
                      "The clear-the-box tree (default: the protocol's, trees/clear_box.yaml or "
                      "trees/vgn_round.yaml)");
  clutter->add_option("--noise", o.noise, "The cell's sensor noise scale (default: the tree's)")
      ->check(CLI::Range(0.0, 10.0));
  clutter->add_option("--set", o.set, "Override a tree entry or component parameter");
  clutter->add_option("--pictures", o.pictures_dir,
                      "Draw every failed attempt into this folder (seed-S-cycle-NN.png)");
  clutter->add_option("--selections", o.selections_dir,
                      "Write every cycle's selection into this folder (seed-S-cycle-NN.json): "
                      "the grasps kept in rank order, then the hands dropped with their reasons");
  clutter->add_option("--shard", o.shard,
                      "i/n: run every n-th run from the i-th (then bench merge); auto: the "
                      "scheduler's (a Slurm array task, a Kubernetes Indexed Job pod)");
  clutter->add_option("--gripper", o.gripper_path,
                      "A gripper file (robots/grippers/) for the sampler; its apertures set which "
                      "objects left count as holdable (default: the tree's, Baxter's)");
}

void add_bench(CLI::App& app, Commands& commands) {
  auto& o = commands.isolation;
  CLI::App* bench = app.add_subcommand("bench", "Measure picking end to end in the simulated cell");
  bench->require_subcommand(1);
  CLI::App* isolation = bench->add_subcommand(
      "isolation", "The paper's isolation experiment: each object in systematic poses");
  isolation
      ->add_option("--objects", o.objects,
                   "'procedural' (scenes/objects/procedural_test_set.yaml) or a mesh folder")
      ->capture_default_str();
  isolation->add_option("--variants", o.variants, "Any of nc_1v,nc_2v,a_2v,svm_1v,svm_2v (all)")
      ->delimiter(',');
  isolation->add_option("--poses", o.poses, "Systematic poses per object")->capture_default_str();
  isolation
      ->add_option("--attempts", o.attempts,
                   "Attempts per variant, objects in turn (0: every object in every pose)")
      ->capture_default_str();
  isolation->add_option("--first", o.first, "Number of the first attempt (e.g. to rerun one)")
      ->capture_default_str();
  isolation->add_option("--seed", o.seed, "Cell seed of attempt 0")
      ->capture_default_str()
      ->check(kSeed);
  isolation->add_option("--jobs", o.jobs, "Processes (the same results for any number)")
      ->capture_default_str();
  isolation->add_option("--report", o.report_path, "Write the report as JSON");
  isolation->add_option("--pictures", o.pictures_dir, "Draw every failed attempt into this folder");
  isolation->add_option("--selections", o.selections_dir,
                        "Write every attempt's selection, cloud and objects into this folder "
                        "(VARIANT-OBJECT-poseK.json, .pcd, -objects.json)");
  isolation->add_option("--tree", o.tree_path, "The pick tree (its `attempt` tree runs)")
      ->capture_default_str();
  isolation->add_option("--noise", o.noise, "The cell's sensor noise scale (default: the tree's)")
      ->check(CLI::Range(0.0, 10.0));
  isolation->add_option("--held-out", o.held_out, "Objects reported apart (comma-separated)")
      ->delimiter(',');
  isolation->add_option("--set", o.set, "Override a tree entry or component parameter");
  isolation->add_option("--shard", o.shard,
                        "i/n: run every n-th attempt from the i-th (then bench merge); auto: the "
                        "scheduler's (a Slurm array task, a Kubernetes Indexed Job pod)");
  add_bench_reach(*bench, commands.reach);
  add_bench_clutter(*bench, commands.clutter);
  CLI::App* merge = bench->add_subcommand(
      "merge", "Join the reports of a bench's shards (--shard i/n) into one report");
  merge->add_option("reports", commands.merge.reports, "The shards' JSON reports")->required();
  merge->add_option("--report", commands.merge.report_path, "Write the merged report as JSON");
}

void add_view(CLI::App& app, antipode::cli::ViewOptions& o) {
  CLI::App* view = app.add_subcommand(
      "view",
      "Write one offline HTML page showing a detection, a clear-the-box run or a tree's trace "
      "in 3D (docs/viewer.md)");
  view->add_option("inputs", o.inputs,
                   "A cloud (.pcd, .ply) and its grasps file (.json), or a clear-the-box report "
                   "(.json); and/or a trace (.jsonl)")
      ->required();
  view->add_option("--out", o.out_path, "The page to write")->capture_default_str();
  view->add_option("--gripper", o.gripper_path,
                   "Gripper file the hands are drawn with (default: Baxter's)");
  view->add_option("--selections", o.selections_dir,
                   "With a report: the folder its bench's --selections filled (each cycle's "
                   "cloud, hands and objects)");
  view->add_option("--pictures", o.pictures_dir,
                   "With a report: the folder its bench's --pictures filled");
  view->add_option("--voxel", o.voxel_m,
                   "With a report: thin each cycle's cloud to one point per voxel of this edge "
                   "(m; 0 keeps every point)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.1));
  view->add_flag("--open", o.open, "Open the page in the desktop's browser (xdg-open)");
}

void add_report(CLI::App& app, antipode::evaluation::ReportOptions& o) {
  CLI::App* report = app.add_subcommand(
      "report", "Write the results report (markdown and PNG charts) from bench reports");
  report->add_option("reports", o.reports, "Bench JSON reports, one section each")->required();
  report->add_option("--out", o.out_path, "The markdown file to write")->required();
  report->add_option("--plots", o.plots_dir,
                     "Folder of the PNG charts (default: images/ beside --out)");
  report->add_option("--notes", o.notes_path, "Hand-written context (markdown, ## sections)");
}

// The paths a command reads that antipode ships (its trees, the default model and robot):
// from any folder, a relative path missing there is taken from the shipped data
// (antipode/core/shipped_data.hpp), so that an installed antipode runs its own trees. Scene
// files are not: the cell resolves them from the tree's folder and its parent, which for a
// shipped tree holds the shipped scenes.
void resolve_shipped_paths(Commands& c) {
  for (std::string* path :
       {&c.run.tree_path, &c.detect.tree_path, &c.scene.tree_path, &c.train.tree_path,
        &c.outcomes.tree_path, &c.eval.tree_path, &c.eval.model_path, &c.isolation.tree_path,
        &c.reach.robot_path, &c.reach.scene_tree, &c.clutter.tree_path, &c.clutter.gripper_path,
        &c.robot_check.robot_path, &c.robot_check.tree_path})
    *path = antipode::resolve_shipped(*path);
  for (std::string& path : c.validate_paths) path = antipode::resolve_shipped(path);
}

void add_robot(CLI::App& app, antipode::cli::RobotCheckOptions& o) {
  CLI::App* robot = app.add_subcommand("robot", "Robot files: check a robot's description");
  robot->require_subcommand(1);
  CLI::App* check = robot->add_subcommand(
      "check",
      "Check a robot file: its arm's kinematics and limits, self-collision, reach over the "
      "cell's box and table, and its fingers against its gripper file (trees/robot_check.yaml)");
  check->add_option("robot", o.robot_path, "Robot file (robots/*/*.yaml)")->required();
  check->add_option("--scene", o.scene_path, "Cell scene whose table and box the reach covers")
      ->capture_default_str();
  check
      ->add_option("--configurations", o.configurations,
                   "Random configurations for the self-collision histogram")
      ->capture_default_str();
  check->add_option("--report", o.report_path, "Write the checks as JSON");
  check->add_option("--tree", o.tree_path, "The checking tree")->capture_default_str();
  add_tree_run_options(*check, o.settings);
}

int dispatch(const CLI::App& app, const Commands& commands) {
  if (app.got_subcommand("run")) return antipode::cli::run_command(commands.run);
  if (app.got_subcommand("detect")) return antipode::cli::detect_command(commands.detect);
  if (app.got_subcommand("scene")) return antipode::cli::scene_command(commands.scene);
  if (app.got_subcommand("train")) return antipode::cli::train_command(commands.train);
  if (app.got_subcommand("outcomes")) return antipode::cli::outcome_data_command(commands.outcomes);
  if (app.got_subcommand("eval-classifier")) {
    return antipode::cli::eval_classifier_command(commands.eval);
  }
  if (app.got_subcommand("validate")) {
    for (const std::string& path : commands.validate_paths)
      if (const int code = antipode::cli::validate_command(path); code != 0) return code;
    return 0;
  }
  if (app.got_subcommand("bench")) {
    const CLI::App* bench = app.get_subcommand("bench");
    if (bench->got_subcommand("reach")) return antipode::cli::bench_reach_command(commands.reach);
    if (bench->got_subcommand("merge")) return antipode::cli::bench_merge_command(commands.merge);
    if (bench->got_subcommand("clutter")) {
      return antipode::cli::bench_clutter_command(commands.clutter);
    }
    return antipode::cli::bench_isolation_command(commands.isolation);
  }
  if (app.got_subcommand("report")) return antipode::cli::report_command(commands.report);
  if (app.got_subcommand("robot")) return antipode::cli::robot_check_command(commands.robot_check);
  if (app.got_subcommand("view")) return antipode::cli::view_command(commands.view);
  if (app.got_subcommand("plugins")) {
    if (!commands.index_directory.empty())
      return antipode::cli::write_index_command(commands.index_directory);
    return commands.check_library.empty()
               ? antipode::cli::plugins_command()
               : antipode::cli::check_plugin_command(commands.check_library);
  }
  if (app.got_subcommand("nodes")) return antipode::cli::nodes_command(commands.node_type);
  std::cout << app.help();
  return antipode::cli::kExitInvalidInput;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace antipode::cli;
  CLI::App app{"antipode: grasp detection and picking with behaviour trees and plugins"};
  app.set_version_flag("--version", std::string("antipode ") + ANTIPODE_VERSION);
  Commands commands;
  add_run(app, commands);
  add_detect(app, commands);
  add_scene(app, commands);
  add_train(app, commands);
  add_eval(app, commands);
  add_outcomes(app, commands);
  add_bench(app, commands);
  add_report(app, commands.report);
  add_view(app, commands.view);
  add_robot(app, commands.robot_check);
  CLI::App* validate = app.add_subcommand(
      "validate", "Check tree files without running them (the first error stops)");
  validate->add_option("trees", commands.validate_paths, "YAML tree files")->required();
  CLI::App* plugins =
      app.add_subcommand("plugins", "List plugin libraries found, loaded and refused, and why");
  CLI::Option* check = plugins->add_option(
      "--check", commands.check_library,
      "Load one library and report its descriptor, ABI and types, or why it cannot load");
  plugins
      ->add_option("--write-index", commands.index_directory,
                   "Write the index of a plugin directory (what each library provides), so "
                   "that trees open only the libraries they need")
      ->excludes(check);
  CLI::App* nodes =
      app.add_subcommand("nodes", "List the node types trees can use, or one's ports");
  nodes->add_option("type", commands.node_type, "A node type, e.g. SampleHands");
  app.require_subcommand(0, 1);
  app.footer(kExamples);  // set last: subcommands made before it do not repeat it
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
    // One line, as every other error: what CLI11 found wrong, and where to look.
    const std::string unknown = unknown_subcommand(app, argc, argv);
    std::cerr << "antipode: error: " << (unknown.empty() ? error.what() : unknown)
              << " (see antipode --help, or the command's --help)\n";
    return kExitInvalidInput;
  }
  try {
    resolve_shipped_paths(commands);
    return dispatch(app, commands);
  } catch (const antipode::InternalError& error) {
    std::cerr << "antipode: internal error: " << error.what() << "\n";
    return kExitInternalError;
  } catch (const antipode::Error& error) {
    std::cerr << "antipode: error: " << error.what() << "\n";
    return kExitInvalidInput;
  } catch (const std::exception& error) {
    std::cerr << "antipode: internal error: " << error.what() << "\n";
    return kExitInternalError;
  } catch (...) {
    std::cerr << "antipode: internal error: an exception of unknown type\n";
    return kExitInternalError;
  }
}
