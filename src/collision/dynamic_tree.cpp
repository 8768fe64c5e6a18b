// Placeholder: implementation pending.
#include "collision/dynamic_tree.h"
