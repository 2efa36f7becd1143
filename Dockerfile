# swarmplan: a multi-stage build. The runtime stage carries only the runtime libraries and the
# settings the server runs with; the build stage installs the dev packages, builds in Release and
# runs the unit tests; the last stage is the runtime with the two binaries and the sample maps.
#
#   docker build -t swarmplan .
#   docker run -p 127.0.0.1:50051:50051 -p 127.0.0.1:9464:9464 -v swarmplan-data:/data swarmplan
#
# `docker build --target runtime` gives the runtime alone; scripts/container-smoke --binaries
# adds binaries built outside to it.

FROM debian:bookworm-slim AS runtime
RUN apt-get update -qq \
 && apt-get install -y -qq --no-install-recommends \
      libgrpc++1.51 libprotobuf32 libabsl20220623 libspdlog1.10 libfmt9 \
      libprometheus-cpp-core1.0 libprometheus-cpp-pull1.0 libsqlite3-0 libhiredis0.14 \
      libyaml-cpp0.7 libpng16-16 ca-certificates \
 && apt-get clean && rm -rf /var/lib/apt/lists/* \
 && useradd --system --uid 10001 --home-dir /data --shell /usr/sbin/nologin swarmplan \
 && mkdir -p /data && chown swarmplan:swarmplan /data
USER swarmplan
VOLUME /data
ENV PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    SWARMPLAN_LISTEN=0.0.0.0:50051 \
    SWARMPLAN_METRICS_ADDRESS=0.0.0.0 \
    SWARMPLAN_METRICS_PORT=9464 \
    SWARMPLAN_DATA_DIR=/data \
    SWARMPLAN_SHUTDOWN_GRACE=20s \
    SWARMPLAN_SERVER=127.0.0.1:50051
EXPOSE 50051 9464
HEALTHCHECK --interval=10s --timeout=3s --start-period=5s --retries=3 \
  CMD ["/usr/local/bin/swarmplan", "health", "--timeout", "2"]
# SIGTERM starts a graceful shutdown: running jobs get SWARMPLAN_SHUTDOWN_GRACE to finish and
# are re-queued in the store otherwise. `docker stop -t 30` leaves room for that.
STOPSIGNAL SIGTERM
ENTRYPOINT ["/usr/local/bin/swarmplan-server"]

FROM debian:bookworm-slim AS build
WORKDIR /src
COPY scripts/install-deps scripts/install-deps
RUN scripts/install-deps --build-only && apt-get clean && rm -rf /var/lib/apt/lists/*
COPY . .
RUN cmake -S . -B /build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSWARMPLAN_WERROR=ON \
      -DSWARMPLAN_BUILD_BENCH=OFF -DSWARMPLAN_SHARED_DIR=/nonexistent \
 && cmake --build /build -j "$(nproc)" --target swarmplan-server swarmplan swarmplan_unit_tests \
 && /build/tests/swarmplan_unit_tests --gtest_brief=1 \
 && scripts/stage-image-files /build /out

FROM runtime
COPY --from=build /out/ /
