#ifndef RODNET_IO_READ_NOTES_H
#define RODNET_IO_READ_NOTES_H

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * What a reader of an input file tells the user besides what it read:
   * what it did to the input (info: "merged coincident nodes ...") and
   * what makes the answer doubtful (warnings). Each is one line without a
   * prefix; the scene runner prints the info after "rodnet: " and the
   * warnings after "warning: ".
   */
  struct ReadNotes
  {
    std::vector<std::string> info;
    std::vector<std::string> warnings;
  };
} // namespace rodnet

#endif
