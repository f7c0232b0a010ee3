#ifndef RODNET_IO_TIME_DRIVE_H
#define RODNET_IO_TIME_DRIVE_H

#include <core/time_function.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Reads the trailing "in time <expression of t>" of the words @p words of
   * an item of a scene entry (activation fields, prescribed displacements
   * and rotations) and removes it from @p words; an empty TimeFunction if
   * there is none. @p context ("entry \"...\", item \"...\": ") starts
   * every message: an empty or unreadable expression is refused here, and
   * the function throws std::invalid_argument naming the time where its
   * value is not finite.
   */
  TimeFunction
  read_in_time(std::vector<std::string> &words,
               const std::string        &entry,
               const std::string        &context);

  /// Whether the item @p text of a scene entry ends in "in time ...", read
  /// by read_in_time(): its value then follows that function of time, not
  /// the load factor.
  bool
  follows_time_function(const std::string &text);

  /// The offset in @p text of the words "in time" that start a function of
  /// time; std::string::npos if there are none.
  std::size_t
  in_time_offset(const std::string &text);
} // namespace rodnet

#endif
