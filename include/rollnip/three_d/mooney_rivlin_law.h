#ifndef rollnip_three_d_mooney_rivlin_law_h
#define rollnip_three_d_mooney_rivlin_law_h

// The law is shared with the 2D body: material/mooney_rivlin_law.h.
#include <rollnip/material/mooney_rivlin_law.h>

#endif
