#include "sim/record_line.h"

namespace canopy::sim {

void RecordLineWriter::write(const StepRecord& record, std::string& out) {
  JsonLine j(out, &numbers_);
  LineOut line(j, schema_, names_, labels_);
  writeObject(line, schema_.step, record);
}

std::string recordLine(const std::vector<std::string>& labels, const StepRecord& record,
                       const RecordSchema& schema) {
  RecordLineWriter writer(labels, schema);
  std::string line;
  writer.write(record, line);
  return line;
}

}  // namespace canopy::sim
