// Placeholder: implementation pending.
#include "collision/broad_phase.h"
