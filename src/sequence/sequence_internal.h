// What the library's other modules need of a sequence run beyond the public API.
#ifndef ORI_SEQUENCE_INTERNAL_H
#define ORI_SEQUENCE_INTERNAL_H

#include <orikin/sequence.h>

// The mechanism the record was run on (borrowed).
const ori_mechanism *ori__record_mechanism(const ori_record *record);

#endif
