#pragma once
// The contact sheet job of a farm submission (`farm submit --contact-sheet FRAME`, docs/FARM.md):
// after every other job has ended, whatever its outcome, the editor renders FRAME of each wedge
// and tiles the pictures, each labelled by its wedge's values, into DIR/contact_sheet.png.
#include "FarmJob.h"
#include "FarmLayout.h"
#include "FarmListing.h"

#include <string>

namespace airtrap::cli {

class FarmContactSheet {
public:
    //! The job, with its script and tile list written. `editor` is the editor's path on the
    //! nodes.
    static FarmJob plan(const FarmListing& listing, const FarmLayout& layout,
                        const std::string& editor, int frame);

    //! Tiles per row: one per value of the last wedged key, so that each row varies that key
    //! and each column holds one value of it; about √n with fewer than two keys.
    static int columns(const FarmListing& listing);

    //! The label of a wedge's tile: its keys and values on one line.
    static std::string label(const FarmWedge& entry);
};

} // namespace airtrap::cli
