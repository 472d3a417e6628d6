#pragma once

// The synthetic CAD models with their ground truth, in one include: the model's data
// and check (cad_model.h), the named models (cad_catalogue.h), the queries on a model
// (cad_queries.h), the sampling (cad_sampling.h), the tessellation
// (cad_tessellation.h) and the organized depth view (cad_depth_view.h).

#include <support/cad_catalogue.h>
#include <support/cad_depth_view.h>
#include <support/cad_model.h>
#include <support/cad_queries.h>
#include <support/cad_sampling.h>
#include <support/cad_tessellation.h>
