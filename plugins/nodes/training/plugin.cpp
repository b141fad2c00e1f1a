// The training_nodes plugin: labelling hands, collecting examples, training and evaluating
// the SVM classifier (docs/training.md).
#include "antipode/plugin/abi.hpp"
#include "nodes.hpp"

namespace {
using namespace antipode::training;

const antipode::PluginFactory kFactories[] = {
    {"node", "NewTrainingSet", "starts an empty training set", nullptr, &register_new_training_set},
    {"node", "LabelHands", "labels hands by the near-antipodal check", nullptr,
     &register_label_hands},
    {"node", "CollectExamples", "appends HOG examples of labelled hands", nullptr,
     &register_collect_examples},
    {"node", "SaveTrainingSet", "writes a training set", nullptr, &register_save_training_set},
    {"node", "LoadTrainingSet", "reads a training set", nullptr, &register_load_training_set},
    {"node", "NewTrialLog", "starts an empty trial log", nullptr, &register_new_trial_log},
    {"node", "CollectTrials", "appends tried hands and their outcomes", nullptr,
     &register_collect_trials},
    {"node", "SaveTrials", "writes one scene's trials", nullptr, &register_save_trials},
    {"node", "MergeTrials", "joins trial files into a training set", nullptr,
     &register_merge_trials},
    {"node", "TrainClassifier", "trains the SVM classifier", nullptr, &register_train_classifier},
    {"node", "CrossValidate", "cross-validates the SVM", nullptr, &register_cross_validate},
    {"node", "EvaluateClassifier", "measures a classifier model", nullptr,
     &register_evaluate_classifier},
    {"node", "CalibrateClassifier", "fits a model's probability of success", nullptr,
     &register_calibrate_classifier},
};

}  // namespace

ANTIPODE_PLUGIN("training_nodes", "0.1.0", kFactories)
