#include "runtime/io/atomic_file.h"

#include "runtime/io/output_transaction.h"

namespace fgsg::rt::io {

bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string& error) {
  OutputTransaction one;
  return one.stage(path, bytes, error) && one.commit(error);
}

}  // namespace fgsg::rt::io
