// Placeholder: implementation pending.
#include "report/svg.h"
