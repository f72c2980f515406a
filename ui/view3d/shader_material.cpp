#include "ui/view3d/shader_material.h"

#include <QUrl>
#include <Qt3DRender/QCullFace>
#include <Qt3DRender/QEffect>
#include <Qt3DRender/QFilterKey>
#include <Qt3DRender/QGraphicsApiFilter>
#include <Qt3DRender/QMaterial>
#include <Qt3DRender/QPolygonOffset>
#include <Qt3DRender/QRenderPass>
#include <Qt3DRender/QShaderProgram>
#include <Qt3DRender/QTechnique>

static void registerResources() { Q_INIT_RESOURCE(resources); }

namespace jl::ui {

void ensureResources() {
    static const bool once = (registerResources(), true);
    (void)once;
}

Qt3DRender::QMaterial* shaderMaterial(const QString& name, Qt3DCore::QNode* parent, ShaderOptions options,
                                      const QString& fragment) {
    ensureResources();
    auto* material = new Qt3DRender::QMaterial(parent);
    auto* effect = new Qt3DRender::QEffect(material);
    auto* technique = new Qt3DRender::QTechnique(effect);
    auto* api = technique->graphicsApiFilter();
    api->setApi(Qt3DRender::QGraphicsApiFilter::OpenGL);
    api->setProfile(Qt3DRender::QGraphicsApiFilter::CoreProfile);
    api->setMajorVersion(3);
    api->setMinorVersion(3);
    // The default forward renderer draws only techniques with this key.
    auto* key = new Qt3DRender::QFilterKey(technique);
    key->setName("renderingStyle");
    key->setValue("forward");
    technique->addFilterKey(key);

    auto* pass = new Qt3DRender::QRenderPass(technique);
    auto* program = new Qt3DRender::QShaderProgram(pass);
    program->setVertexShaderCode(Qt3DRender::QShaderProgram::loadSource(QUrl("qrc:/shaders/" + name + ".vert")));
    program->setFragmentShaderCode(Qt3DRender::QShaderProgram::loadSource(
        QUrl("qrc:/shaders/" + (fragment.isEmpty() ? name : fragment) + ".frag")));
    pass->setShaderProgram(program);
    if (options != ShaderOptions::Solid) {
        auto* cull = new Qt3DRender::QCullFace(pass);
        cull->setMode(Qt3DRender::QCullFace::NoCulling);
        pass->addRenderState(cull);
    }
    if (options == ShaderOptions::TwoSidedOnAFace) {
        auto* offset = new Qt3DRender::QPolygonOffset(pass);
        offset->setScaleFactor(-1.0f);
        offset->setDepthSteps(-4.0f);
        pass->addRenderState(offset);
    }
    technique->addRenderPass(pass);
    effect->addTechnique(technique);
    material->setEffect(effect);
    return material;
}

}  // namespace jl::ui
