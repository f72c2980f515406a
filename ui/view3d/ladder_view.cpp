#include "ui/view3d/ladder_view.h"

#include "jl/ladder/ladder.h"
#include "jl/scene/ladder_blocks.h"
#include "ui/teaching/events_panel.h"
#include "ui/view3d/block_instances.h"
#include "ui/view3d/block_shapes.h"
#include "ui/view3d/ribbon_instances.h"
#include "ui/view3d/room.h"
#include "ui/view3d/scale_mark.h"
#include "ui/view3d/strip_entity.h"

#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QThread>
#include <QToolTip>
#include <QWheelEvent>
#include <Qt3DExtras/QForwardRenderer>
#include <Qt3DRender/QCamera>
#include <Qt3DRender/QRenderCapture>
#include <Qt3DRender/QRenderSettings>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jl::ui {

namespace {
constexpr float kOrbitDegreesPerPixel = 0.3f;
constexpr float kLookDegreesPerPixel = 0.15f;
constexpr double kRibbonDistanceInBlocks = 40;  // ribbons drawn while the eye is closer than this

// The eight corners of a box of the given sizes at `pose` (in the plane, z = 0 its middle).
void addBox(std::vector<QVector3D>& corners, const jl::Pose& pose, float across, float along, float out) {
    const float x = float(pose.position.x()), y = float(pose.position.y());
    const float c = float(std::cos(pose.angle)), s = float(std::sin(pose.angle));
    for (const float u : {-across / 2, across / 2})
        for (const float v : {-along / 2, along / 2})
            for (const float w : {-out / 2, out / 2}) corners.emplace_back(x + c * u - s * v, y + s * u + c * v, w);
}
void addCorners(std::vector<QVector3D>& corners, const jl::Pose& pose, const BlockShape& shape) {
    addBox(corners, pose, shape.across, shape.along, shape.out);
}
// Software OpenGL (Mesa's llvmpipe) rasterises with a thread per core, all
// woken at every frame: on two cores they took the simulation thread's core
// as often as the other one, and a 1,000-block ladder, whose engine needs
// all of a core late in its run, fell further behind real time. With one
// thread fewer (one on two cores) it kept pace better, at the same CPU per
// frame (docs/desktop-performance.md). Mesa reads this when the first
// OpenGL context is made, hence before the view's; the user's own setting
// stands, and other drivers ignore it.
Qt3DRender::API openGlLeavingACore() {
    if (!qEnvironmentVariableIsSet("LP_NUM_THREADS"))
        qputenv("LP_NUM_THREADS", QByteArray::number(std::max(1, QThread::idealThreadCount() - 1)));
    return Qt3DRender::API::OpenGL;
}
}  // namespace

LadderView::LadderView() : Qt3DExtras::Qt3DWindow(nullptr, openGlLeavingACore()) {
    auto* forward = defaultFrameGraph();
    forward->setClearColor(QColor(201, 207, 216));
    // Blocks are instanced far from their unit cube: the cube's bounds say nothing about where they are.
    forward->setFrustumCullingEnabled(false);
    // The capture node sits above the forward renderer so it sees what is drawn.
    capture_ = new Qt3DRender::QRenderCapture;
    forward->setParent(capture_);
    setActiveFrameGraph(capture_);
    // Redraw only when something changed: an idle view costs nothing.
    renderSettings()->setRenderPolicy(Qt3DRender::QRenderSettings::OnDemand);

    root_ = new Qt3DCore::QEntity;
    room_ = new Room(root_);
    blocks_ = new BlockInstances(root_);
    ribbons_ = new RibbonInstances(root_, false);
    centralRibbons_ = new RibbonInstances(root_, true);
    dragLine_ = new StripEntity(root_, true);
    springs_ = new StripEntity(root_, true);
    scale_ = new ScaleMark(root_);
    dragLine_->setColor(QColor(225, 40, 40));
    springs_->setColor(QColor(70, 70, 80));  // the particles' grey
    setRootEntity(root_);
    camera()->lens()->setPerspectiveProjection(40, 1.6f, 0.01f, 100);
    updateCamera();

    walkTimer_.setInterval(16);
    connect(&walkTimer_, &QTimer::timeout, this, &LadderView::walkTick);
}

void LadderView::setScene(const jl::Scene& scene, bool resetCamera) {
    const bool wasWhole = showsWholeLadder();
    std::vector<BlockShape> shapes = blockShapes(scene);
    const double extent = ladderExtent(scene);
    // More or fewer blocks, or longer ones: the view that fitted no longer does.
    auto sized = [](const BlockShape& a, const BlockShape& b) {
        return a.across == b.across && a.along == b.along && a.out == b.out;
    };
    const bool resized =
        extent != extent_ || !std::equal(shapes.begin(), shapes.end(), shapes_.begin(), shapes_.end(), sized);
    shapes_ = shapes;
    blocks_->setShapes(std::move(shapes));
    extent_ = extent;
    room_->fitTo(extent_, scene.floor ? std::optional<double>(scene.floor->height) : std::nullopt);
    ladder_ = scene.ladder;
    blockSpecs_ = scene.ladder ? jl::ladderBlocks(*scene.ladder) : std::vector<jl::BlockSpec>{};
    if (scene.ladder) {
        blockWidth_ = scene.ladder->block.width;
        blockLength_ = scene.ladder->block.length;
        ribbonSpec_ = scene.ladder->ribbons;
        for (RibbonInstances* r : {ribbons_, centralRibbons_}) r->setSpec(ribbonSpec_, blockWidth_);
    }
    view_ = scene.view;
    ribbonsStale_ = true;
    restructure_.setScene(scene);
    if (resetCamera) {
        hand_ = jl::Vec2::Zero();
        shownPoses_.clear();  // the old scene's blocks say nothing of the new one's
        resetView();
    } else if (resized && (wasWhole || !showsSomeOfLadder())) {
        // The whole ladder was in view: so it stays. A view of part of it
        // (the top of a long ladder, where the ripple starts) is left alone:
        // blocks added or taken away at the bottom do not move the top.
        // A view of nothing (the bottom of a long ladder made short by an
        // undo) is of no use: the ladder is framed.
        frameLadder();
        frameOnNextFrame_ = true;
    }
}

void LadderView::setFollow(bool on) {
    follow_ = on;
    followedCentre_.reset();
}

void LadderView::showFrame(const jl::Frame& frame) { showFrame(std::make_shared<const jl::Frame>(frame)); }

void LadderView::showFrame(std::shared_ptr<const jl::Frame> shared) {
    if (!shared) return;
    restructure_.showFrame(shared);
    const jl::Frame& frame = *shared;
    if (!frame.dragging) grabbed_ = -1;
    // Swapped and assigned, not moved and copied: the lists keep their room
    // (240 kB a frame for 10,000 blocks, each a fresh page-faulting block).
    if (frame.time != shownTime_) {
        earlierPoses_.swap(shownPoses_);
        earlierTime_ = shownTime_;
    }
    shownPoses_.assign(frame.poses.begin(), frame.poses.end());
    shownTime_ = frame.time;
    const auto held = std::find(frame.held.begin(), frame.held.end(), true);
    hand_ = held != frame.held.end() ? frame.poses[size_t(held - frame.held.begin())].position : jl::Vec2::Zero();
    if (follow_ && !frame.poses.empty()) {
        jl::Vec2 centre = jl::Vec2::Zero();
        for (const jl::Pose& p : frame.poses) centre += p.position;
        centre /= double(frame.poses.size());
        if (followedCentre_) {
            const jl::Vec2 d = centre - *followedCentre_;
            camera_.shift(QVector3D(float(d.x()), float(d.y()), 0));
            updateCamera();
        }
        followedCentre_ = centre;
    }
    if (frameOnNextFrame_) {
        frameOnNextFrame_ = false;
        frameLadder();
    }
    // At an event's instant, the blocks its hinge joins: where to look.
    pointedAt_.clear();
    for (const int j : hingesAtInstant(frame)) pointedAt_.insert(pointedAt_.end(), {j - 1, j});
    blocks_->showFrame(frame, frame.dragging ? grabbed_ : -1, highlighted());
    shownFrame_ = shared;
    ribbonsStale_ = true;
    showRibbons();
    // The scene's springs in the plane of the pins and particles they join.
    buildSprings(*springs_, frame, 0.0f, float(std::max(0.0008, camera_.distance() * 0.0015)));
    // The spring is drawn in front of the blocks, on the face toward the viewer.
    buildDragLine(*dragLine_, frame, float(blockWidth_ / 2 + 0.002),
                  float(std::max(0.0015, camera_.distance() * 0.003)));
    if (restructure_.joining()) showRestructure();  // the join drag's line over the frame's
    if (frame.dragging && grabbed_ < 0) {
        // Which block: the one whose centre is nearest the grabbed point.
        double best = 1e300;
        for (size_t i = 0; i < frame.poses.size(); ++i) {
            const double d = (frame.poses[i].position - frame.dragFrom).squaredNorm();
            if (d < best) best = d, grabbed_ = int(i);
        }
    }
}

void LadderView::resetView() {
    camera_.reset(view_, extent_);
    // A scene that says where to look is looked at there; otherwise the
    // whole ladder, now and again when its first frame is shown.
    // (A framing still due from an earlier scene is dropped: this one says where to look.)
    const jl::ViewSpec unsaid;
    frameOnNextFrame_ = view_.target == unsaid.target && view_.distance == unsaid.distance;
    if (frameOnNextFrame_) frameLadder();
    updateCamera();
}

void LadderView::frameLadder() {
    const std::vector<QVector3D> corners = ladderCorners();
    camera_.frame(corners, height() > 0 ? float(width()) / float(height()) : 1.6f);
    updateCamera();
}

bool LadderView::frameMotion() {
    constexpr double kShare = 0.2;  // of the largest motion that counts as moving
    constexpr int kNeighbours = 2;  // blocks either side, for context
    constexpr size_t kReach = 3;    // blocks apart that still make one moving stretch
    const size_t n = std::min({shownPoses_.size(), earlierPoses_.size(), shapes_.size()});
    std::vector<double> moved(n);
    double most = 0;
    for (size_t i = 0; i < n; ++i) {
        // How far the block's ends went: its centre's path and its turn.
        moved[i] = (shownPoses_[i].position - earlierPoses_[i].position).norm() +
                   std::abs(shownPoses_[i].angle - earlierPoses_[i].angle) * shapes_[i].along / 2;
        most = std::max(most, moved[i]);
    }
    if (n == 0 || shownTime_ == earlierTime_ || !(most > 1e-6)) {
        frameLadder();
        return false;
    }
    // The stretch around the block that moved most, as far as blocks that
    // also move come within kReach of each other: a ladder can move at both
    // ends at once (the top swinging, the bottom knocking), and framing both
    // is framing the whole.
    const auto arg = size_t(std::max_element(moved.begin(), moved.end()) - moved.begin());
    const auto moving = [&](size_t i) { return moved[i] >= kShare * most; };
    size_t first = arg, last = arg;
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t j = 1; j <= kReach && first >= j; ++j)
            if (moving(first - j)) {
                first -= j, grew = true;
                break;
            }
        for (size_t j = 1; j <= kReach && last + j < n; ++j)
            if (moving(last + j)) {
                last += j, grew = true;
                break;
            }
    }
    first = first >= size_t(kNeighbours) ? first - kNeighbours : 0;
    last = std::min(n - 1, last + kNeighbours);
    std::vector<QVector3D> corners;
    for (size_t i = first; i <= last; ++i) addCorners(corners, shownPoses_[i], shapes_[i]);
    camera_.frame(corners, height() > 0 ? float(width()) / float(height()) : 1.6f);
    updateCamera();
    return true;
}

bool LadderView::showsWholeLadder() const {
    // A little out of the view still counts (a block swung out past the edge).
    constexpr float kSlack = 1.25f;
    const QMatrix4x4 viewProjection = camera()->projectionMatrix() * camera()->viewMatrix();
    for (const QVector3D& c : ladderCorners()) {
        const QVector4D clip = viewProjection * QVector4D(c, 1);
        if (clip.w() <= 0 || std::abs(clip.x()) > kSlack * clip.w() || std::abs(clip.y()) > kSlack * clip.w())
            return false;
    }
    return true;
}

bool LadderView::showsSomeOfLadder() const {
    const QMatrix4x4 viewProjection = camera()->projectionMatrix() * camera()->viewMatrix();
    // The ladder's outline on screen, in normalised coordinates (-1 .. 1 in view).
    float left = INFINITY, right = -INFINITY, bottom = INFINITY, top = -INFINITY;
    for (const QVector3D& c : ladderCorners()) {
        const QVector4D clip = viewProjection * QVector4D(c, 1);
        if (clip.w() <= 0) return true;  // it reaches behind the eye: around it, so in view
        left = std::min(left, clip.x() / clip.w()), right = std::max(right, clip.x() / clip.w());
        bottom = std::min(bottom, clip.y() / clip.w()), top = std::max(top, clip.y() / clip.w());
    }
    return left <= 1 && right >= -1 && bottom <= 1 && top >= -1;
}

std::vector<QVector3D> LadderView::ladderCorners() const {
    std::vector<QVector3D> corners;
    // Where the blocks can hang: straight down from the hand (the held
    // block's centre; the origin when nothing is held). One hinge's held
    // block is the lower one, and the upper one flips to hang below it.
    addBox(corners, {{hand_.x(), hand_.y() - extent_ / 2}, 0}, float(blockLength_), float(extent_), float(blockWidth_));
    const size_t n = std::min(shownPoses_.size(), shapes_.size());
    for (size_t i = 0; i < n; ++i) addCorners(corners, shownPoses_[i], shapes_[i]);
    return corners;
}

void LadderView::orbit(float yawDegrees, float pitchDegrees) {
    camera_.orbit(yawDegrees, pitchDegrees);
    updateCamera();
}

void LadderView::setWalkMode(bool on) {
    if (walk_ == on) return;
    walk_ = on;
    keysDown_.clear();
    emit walkModeChanged(on);
}

int LadderView::blocksDrawn() const { return blocks_->drawnCount(); }

void LadderView::updateCamera() {
    camera_.apply(camera());
    blocks_->setView(camera()->projectionMatrix() * camera()->viewMatrix(), QSize(width(), height()));
    scale_->place(camera_, height(), height() > 0 ? float(width()) / float(height()) : 1.6f);
    showRibbons();
}

// Ribbons are a few pixels wide at best when the whole of a long ladder is
// in view, yet they cost more to draw than all the blocks: they show close
// up, and then only those of the blocks near the view (close to the top of
// 10,000 blocks, a few dozen of them). So a turn of the camera may need
// others, and a new frame always does.
void LadderView::showRibbons() {
    const jl::Frame* frame = shownFrame_.get();
    BlockSpan near;
    if (frame && (ladder_ || !frame->ribbons.empty()) && ribbonSpec_.visible &&
        camera_.distance() < kRibbonDistanceInBlocks * blockLength_) {
        const size_t n = std::min(frame->poses.size(), blockSpecs_.size());
        near = blocksNearView(camera()->projectionMatrix() * camera()->viewMatrix(), std::span(frame->poses).first(n),
                              float(blockLength_));
    }
    if (!ribbonsStale_ && near == ribbonsNear_) return;
    ribbonsStale_ = false;
    ribbonsNear_ = near;
    std::vector<jl::RibbonFrame> ribbons;
    if (near.first <= near.last) {
        // From the block above the first (its hinge's ribbons reach down), at
        // an even number: a hinge's faces alternate with its number, so a
        // stretch made from an odd block would put them on the other faces.
        const int first = std::max(near.first - 1, 0) & ~1;
        if (!frame->ribbons.empty()) {
            // Two a hinge, hinge j's (below block j - 1) from 2 (j - 1).
            const size_t from = std::min(2 * size_t(first), frame->ribbons.size());
            const size_t to = std::min(2 * size_t(near.last + 1), frame->ribbons.size());
            ribbons.assign(frame->ribbons.begin() + long(from), frame->ribbons.begin() + long(to));
        } else if (ladder_) {
            const size_t n = std::min({frame->poses.size(), blockSpecs_.size(), frame->hinges.size() + 1});
            const size_t count = std::min(size_t(near.last + 2), n) - size_t(first);
            ribbons = jl::ladderRibbons(*ladder_, std::span(blockSpecs_).subspan(size_t(first), count),
                                        std::span(frame->poses).subspan(size_t(first), count),
                                        std::span(frame->hinges).subspan(size_t(first), count - 1));
        }
    }
    for (RibbonInstances* r : {ribbons_, centralRibbons_}) r->showRibbons(ribbons);
}

std::optional<jl::Vec2> LadderView::planePoint(const QPointF& pixel) const {
    const QRect viewport(0, 0, width(), height());
    const QMatrix4x4 view = camera()->viewMatrix();
    const QMatrix4x4 proj = camera()->projectionMatrix();
    const float y = float(height() - pixel.y());
    const QVector3D nearP = QVector3D(float(pixel.x()), y, 0).unproject(view, proj, viewport);
    const QVector3D farP = QVector3D(float(pixel.x()), y, 1).unproject(view, proj, viewport);
    const QVector3D d = farP - nearP;
    if (std::abs(d.z()) < 1e-9f) return std::nullopt;
    const float s = -nearP.z() / d.z();
    if (s < 0) return std::nullopt;
    const QVector3D hit = nearP + s * d;
    return jl::Vec2(hit.x(), hit.y());
}

QPointF LadderView::pixelOf(const jl::Vec2& point) const {
    const QRect viewport(0, 0, width(), height());
    const QVector3D p = QVector3D(float(point.x()), float(point.y()), 0)
                            .project(camera()->viewMatrix(), camera()->projectionMatrix(), viewport);
    return {p.x(), height() - p.y()};
}

void LadderView::mousePressEvent(QMouseEvent* e) {
    lastMouse_ = e->position();
    if (e->button() == Qt::RightButton) rightPressAt_ = e->position();
    if (e->button() == Qt::LeftButton && !walk_) {
        const auto p = planePoint(e->position());
        const auto grab = p ? grabAt(*p) : std::nullopt;
        if (grab && (e->modifiers() & Qt::ShiftModifier)) {
            turning_.emplace(grab->block, shownPoses_[size_t(grab->block)].position, *p);
            turnShownTime_ = shownTime_;
            turnClock_.start();
        } else if (p && restructure_.press(*p, metresOf(RestructureGesture::kReachPixels, e->position()))) {
            showRestructure();  // by a hinge: selected; at a free corner: a join drag
        } else if (grab) {
            showRestructure();  // the selection, if any, is dropped
            dragging_ = true;
            grabbed_ = -1;
            emit dragBegun(*p, grab->block, grab->local, shownTime_);
        } else {
            showRestructure();
            orbiting_ = true;  // empty space: turn the view, as most 3-D programs do
        }
    }
}

std::optional<LadderView::Grab> LadderView::grabAt(const jl::Vec2& point) const {
    constexpr double margin = 0.002;  // m
    const size_t n = std::min(shapes_.size(), shownPoses_.size());
    for (size_t i = n; i-- > 0;) {
        const jl::Vec2 local = jl::rotate(-shownPoses_[i].angle, point - shownPoses_[i].position);
        if (std::abs(local.x()) <= shapes_[i].across / 2 + margin &&
            std::abs(local.y()) <= shapes_[i].along / 2 + margin)
            return Grab{int(i), local};
    }
    return std::nullopt;
}

void LadderView::mouseMoveEvent(QMouseEvent* e) {
    const QPointF delta = e->position() - lastMouse_;
    lastMouse_ = e->position();
    if (dragging_) {  // until the release, whatever else the buttons do
        if (const auto p = planePoint(e->position())) emit dragMoved(*p);
    } else if (restructure_.joining()) {
        if (const auto p = planePoint(e->position()))
            restructure_.dragTo(*p, metresOf(RestructureGesture::kSnapPixels, e->position()));
        showRestructure();
    } else if (turning_) {
        if (const auto p = planePoint(e->position())) turning_->moveTo(*p, double(turnClock_.nsecsElapsed()) * 1e-9);
        // What the release will give, beside the pointer.
        const double degrees = TurnGesture::snapped(turning_->swept()) * 180 / std::numbers::pi;
        QToolTip::showText(e->globalPosition().toPoint(),
                           degrees == 0 ? tr("Turn: sweep at least 45 degrees")
                                        : tr("Turn block %1 by %2 degrees").arg(turning_->block()).arg(degrees));
    } else if ((e->buttons() & Qt::RightButton) || (orbiting_ && (e->buttons() & Qt::LeftButton))) {
        if (walk_)
            camera_.lookAround(-float(delta.x()) * kLookDegreesPerPixel, float(delta.y()) * kLookDegreesPerPixel);
        else
            camera_.orbit(-float(delta.x()) * kOrbitDegreesPerPixel, float(delta.y()) * kOrbitDegreesPerPixel);
        updateCamera();
    } else if (e->buttons() & Qt::MiddleButton) {
        camera_.pan(float(delta.x()) / float(height()), float(delta.y()) / float(height()));
        updateCamera();
    } else if (walk_ && (e->buttons() & Qt::LeftButton)) {
        camera_.lookAround(-float(delta.x()) * kLookDegreesPerPixel, float(delta.y()) * kLookDegreesPerPixel);
        updateCamera();
    }
}

void LadderView::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) orbiting_ = false;
    if (e->button() == Qt::LeftButton && dragging_) {
        dragging_ = false;
        emit dragEnded();
    }
    if (e->button() == Qt::LeftButton && turning_) {
        if (const auto p = planePoint(e->position())) turning_->moveTo(*p, double(turnClock_.nsecsElapsed()) * 1e-9);
        const auto turn = turning_->turn();
        turning_.reset();
        QToolTip::hideText();
        if (turn) emit turnGiven(turn->block, turn->angle, turn->duration, turnShownTime_);
    }
    const auto p = planePoint(e->position());
    if (e->button() == Qt::LeftButton && restructure_.joining())
        give(p ? restructure_.release(*p, metresOf(RestructureGesture::kSnapPixels, e->position())) : std::nullopt);
    const QPointF moved = e->position() - rightPressAt_;
    if (e->button() == Qt::RightButton && p && !walk_ && moved.manhattanLength() < 4) {
        restructure_.popMenu(nullptr, *p, metresOf(RestructureGesture::kReachPixels, e->position()),
                             e->globalPosition().toPoint(), [this](GivenAction a) { give(a); });
        showRestructure();
    }
}

double LadderView::metresOf(double pixels, const QPointF& at) const {
    const auto a = planePoint(at), b = planePoint(at + QPointF(pixels, 0));
    return a && b ? (*b - *a).norm() : 0.0;
}

std::vector<int> LadderView::highlighted() const {
    std::vector<int> lit = pointedAt_;
    for (const int b : restructure_.selectedBlocks()) lit.push_back(b);
    return lit;
}

void LadderView::showRestructure() {
    if (!restructure_.shown().poses.empty()) blocks_->showFrame(restructure_.shown(), -1, highlighted());
    jl::Frame line;
    if (const auto ends = restructure_.joinLine()) {
        line.dragging = true;
        line.dragFrom = ends->first;
        line.dragTo = ends->second;
    }
    dragLine_->setColor(restructure_.snapped() ? QColor(40, 170, 70) : QColor(225, 40, 40));
    buildDragLine(*dragLine_, line, float(blockWidth_ / 2 + 0.002),
                  float(std::max(0.0015, camera_.distance() * 0.003)));
}

void LadderView::give(std::optional<GivenAction> given) {
    showRestructure();
    if (given) emit actionGiven(given->action, given->text);
}

void LadderView::wheelEvent(QWheelEvent* e) {
    const float steps = float(e->angleDelta().y()) / 120.0f;
    // Toward the point of the ladder's plane under the pointer; walking, or
    // with the plane out of sight, toward the middle of the view.
    const auto p = walk_ ? std::nullopt : planePoint(e->position());
    if (p)
        camera_.zoomAbout(steps, QVector3D(float(p->x()), float(p->y()), 0));
    else
        camera_.zoom(steps);
    updateCamera();
}

void LadderView::keyPressEvent(QKeyEvent* e) {
    const int k = e->key();
    if (k == Qt::Key_Home) {
        resetView();
        return;
    }
    if (k == Qt::Key_Delete && restructure_.selectedHinge() > 0) return give(restructure_.cutSelected());
    if (k == Qt::Key_Escape && walk_) {
        setWalkMode(false);
        return;
    }
    const bool walkKey =
        k == Qt::Key_W || k == Qt::Key_A || k == Qt::Key_S || k == Qt::Key_D || k == Qt::Key_Q || k == Qt::Key_E;
    if (walk_ && walkKey && !(e->modifiers() & Qt::ControlModifier)) {
        if (!e->isAutoRepeat()) keysDown_.insert(k);
        if (!walkTimer_.isActive()) {
            walkClock_.start();
            walkTimer_.start();
        }
        return;
    }
    if (!e->isAutoRepeat() || k == Qt::Key_Left || k == Qt::Key_Right || k == Qt::Key_Comma || k == Qt::Key_Period)
        emit unhandledKey(QKeySequence(e->keyCombination()));
}

void LadderView::keyReleaseEvent(QKeyEvent* e) {
    if (!e->isAutoRepeat()) keysDown_.remove(e->key());
}

void LadderView::resizeEvent(QResizeEvent* e) {
    Qt3DExtras::Qt3DWindow::resizeEvent(e);
    updateCamera();
}

// Walking speed follows the room's size: a person's pace in a normal room.
void LadderView::walkTick() {
    const float dt = std::min(0.1f, float(walkClock_.restart()) / 1000.0f);
    if (keysDown_.isEmpty()) {
        walkTimer_.stop();
        return;
    }
    const float speed = 1.2f * std::max(1.0f, float(extent_) / 1.2f) * dt;
    auto down = [this](int k) { return keysDown_.contains(k) ? 1.0f : 0.0f; };
    camera_.walk((down(Qt::Key_W) - down(Qt::Key_S)) * speed, (down(Qt::Key_D) - down(Qt::Key_A)) * speed,
                 (down(Qt::Key_E) - down(Qt::Key_Q)) * speed);
    updateCamera();
}

}  // namespace jl::ui
