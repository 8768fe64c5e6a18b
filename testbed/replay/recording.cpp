// Placeholder: implementation pending.
#include "replay/recording.h"
