// Placeholder: implementation pending.
#include "collision/manifold.h"
