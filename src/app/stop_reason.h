/* app/stop_reason: names and one-line explanations of scaf_stop_reason
 * (include/scaf/scaf.h), for the terminal, the JSON reports and the API. */
#ifndef SCAF_APP_STOP_REASON_H
#define SCAF_APP_STOP_REASON_H

#include "scaf/scaf.h"

/* What the reason means, for a person ("the iteration cap was
 * reached", ...); static. */
const char *stop_reason_explained(scaf_stop_reason reason);

#endif /* SCAF_APP_STOP_REASON_H */
