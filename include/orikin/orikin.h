/// orikin: umbrella header. Include this, or only the headers of the modules you use.
#ifndef ORIKIN_ORIKIN_H
#define ORIKIN_ORIKIN_H

#include "actuation.h"
#include "arrangement.h"
#include "authoring.h"
#include "axioms.h"
#include "base.h"
#include "collection.h"
#include "collision.h"
#include "compliant.h"
#include "fab.h"
#include "flat.h"
#include "fold.h"
#include "formats.h"
#include "generate.h"
#include "kinematics.h"
#include "layers.h"
#include "math.h"
#include "pattern.h"
#include "regularize.h"
#include "render.h"
#include "sequence.h"
#include "tolerance.h"
#include "trajectory.h"
#include "unfold.h"

#endif
