#pragma once
// Threshold segmentation of the spot's closed connected domain (paper 000 steps 4–5) and the
// image-level checks the verdict needs (second spot, saturation). Thin bright features that
// touch the spot (roads, field edges) are cut off the domain by a morphological opening, the
// way paper 001's erosion step removes ground texture.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace lwb::core::footprint {

struct SegmentParams {
    double thresholdFactor = 0.1353352832;  ///< threshold = bg + factor·(peak − bg); 1/e² (paper 001 eq. 3)
    int peakSmooth = 3;        ///< box size (odd, px) smoothing the ROI before the peak is taken; 1 = raw
    bool fillHoles = true;     ///< close the domain: dark pixels enclosed by it belong to it
    int openingRadius = 2;     ///< cut features narrower than 2r+1 px (roads) off the domain; 0 = off
    double minPeakSnr = 6.0;   ///< (peak − bg)/noise below this: no spot (unless the local look passes)
    /// Peaks from localLookFrom·minPeakSnr up get a second look against a ring (ringInnerPx to
    /// ringOuterPx around the peak): one that stands localSnrFloor·minPeakSnr ring-σ, or
    /// textureSnr σ of the ring's pixel-scale texture, above the ring's median is kept as a
    /// faint spot (doubtful), for ground whose large bright and dark areas inflate the ROI-wide
    /// σ (and the ring's, when the ring crosses them).
    double localLookFrom = 0.6;
    double localSnrFloor = 0.8;
    double textureSnr = 14.4;
    double ringInnerPx = 8, ringOuterPx = 12;
    int minPixels = 6;         ///< a domain smaller than this: no spot
    double secondSpotMinSeparation = 4.0;  ///< px between two peaks to call them two spots
};

struct SpotDomain {
    bool found = false;
    std::string why;              ///< when !found: what was missing
    int width = 0, height = 0;    ///< ROI size
    int peakX = 0, peakY = 0;     ///< brightest (smoothed) pixel
    double peak = 0;              ///< smoothed peak value (DN)
    double peakSnr = 0;           ///< (peak − bg)/noise
    double localPeakSnr = 0;      ///< the ring look's SNR, when the ROI-wide one was too low
    double localTextureSnr = 0;   ///< the same against the ring's pixel-scale texture σ
    bool faint = false;           ///< found by the ring look only: the verdict marks it doubtful
    double threshold = 0;         ///< DN
    std::vector<int> pixels;      ///< domain pixels, index y·width + x
    std::vector<unsigned char> mask;  ///< width·height, 1 inside the domain
    bool touchesBorder = false;   ///< a domain pixel lies on the ROI border
    int saturatedPixels = 0;      ///< domain pixels at or above the saturation level
    double secondPeakFraction = 0;  ///< strongest separate peak, (p2 − bg)/(peak − bg); 0 if none
    int secondPeakX = -1, secondPeakY = -1;
};

/// Segments the spot around the brightest smoothed pixel of a CV_32FC1 ROI.
SpotDomain segmentSpot(const cv::Mat& roi, double background, double noise, double saturationDn,
                       const SegmentParams& params);


}  // namespace lwb::core::footprint
