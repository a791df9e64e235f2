package io.concord.sim;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.console.Browser;
import io.concord.console.Console;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;

import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.WebElement;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The hospital view in a real headless Chromium: a transport asked for on the page moves a chair,
 * shows the traffic agent's reservations of its route, and opens a door.
 */
class HospitalConsoleTest {

    @Test
    void aTransportAskedForInTheBrowserMovesAChairAndOpensADoor() throws Exception {
        HospitalMap map = HospitalMap.defaultHospital();
        try (Platform platform = Platform.builder().name("hospital-ui").ports(new PortRange(7521, 80, 10)).build()) {
            HospitalWorld world = HospitalWorld.builder(map).seed(2010).build();
            world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
            Hospital hospital = Hospital.start(platform, world, line -> { });
            world.attach(platform.runtime(), 20);
            platform.startAgent("medical", new MedicalAgent(line -> { }));
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            platform.startAgent("desk", desk);
            try (Console console = Console.start(platform, Console.Config.port(0).withRecordings(java.nio.file.Path.of("target", "recordings")));
                 Browser browser = new Browser()) {
                console.addView(new HospitalView(world, hospital, desk));
                String recording = "hospital-" + System.nanoTime() + ".jsonl";
                console.startRecording(recording);
                // The ward is ready when every planner knows every door (asked on the loop).
                while (true) {
                    CompletableFuture<Boolean> ready = new CompletableFuture<>();
                    platform.runtime().execute(() -> ready.complete(hospital.ready()));
                    if (ready.get(10, TimeUnit.SECONDS)) {
                        break;
                    }
                    Thread.onSpinWait();
                }
                browser.driver.get(console.uri());
                WebElement tab = browser.until(d -> d.findElement(By.cssSelector("nav button[data-view='hospital']")));
                tab.click();
                WebElement chair = browser.until(d -> d.findElement(By.id("chair-chair1")));
                String startX = chair.getAttribute("data-x");
                String startY = chair.getAttribute("data-y");
                browser.screenshot("hospital-before");
                // Labelled: every door by its id, the rooms and corridors by name.
                browser.until(d -> {
                    try {
                        return d.findElement(By.id("label-door-A2")).getText().equals("A2")
                                && d.findElement(By.id("legend-door-closed")).getText().equals("door closed")
                                && d.findElement(By.id("legend-queued")).getText().equals("queued after it")
                                && d.findElements(By.cssSelector("text[id^='label-area-']")).stream().anyMatch(t -> t.getText().equals("Room A2"));
                    } catch (org.openqa.selenium.NoSuchElementException | org.openqa.selenium.StaleElementReferenceException e) {
                        return false; // the map is drawn again with each snapshot
                    }
                });
                browser.until(d -> d.findElement(By.id("action-transport"))).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("asked medical for a transport from node 3 to node 9"));
                browser.until(d -> {
                    WebElement c = d.findElement(By.id("chair-chair1"));
                    return !c.getAttribute("data-x").equals(startX) || !c.getAttribute("data-y").equals(startY);
                });
                // The traffic agent's reservations on the map: a ring round a node of chair1's route, chair1's turn.
                browser.until(d -> d.findElements(By.cssSelector("circle[id^='reserved-'][data-queue='chair1']")).size() > 0);
                // Its way west along ward A's two-lane corridor passes node 4 in lane 1: a ring at that lane's point.
                browser.until(d -> d.findElements(By.cssSelector("circle[id='reserved-4-lane-1'][data-queue='chair1']")).size() > 0);
                // One colour a chair: its body, its route and its reservations (redrawn with each snapshot: read at once).
                browser.until(d -> {
                    try {
                        String body = d.findElement(By.id("chair-chair1")).getAttribute("fill");
                        return body.equals(HospitalView.colour("chair1"))
                                && body.equals(d.findElement(By.id("route-chair1")).getAttribute("stroke"))
                                && body.equals(d.findElement(By.cssSelector("circle[id^='reserved-'][data-queue='chair1']")).getAttribute("stroke"));
                    } catch (org.openqa.selenium.NoSuchElementException | org.openqa.selenium.StaleElementReferenceException e) {
                        return false;
                    }
                });
                assertTrue(!HospitalView.colour("chair1").equals(HospitalView.colour("chair2")), "each chair a colour of its own");
                assertTrue(browser.driver.findElement(By.id("chairs")).getText().lines().noneMatch(l -> l.contains("-0.00 m/s")),
                        "a chair standing still has no sign");
                // Every chair's pose with its heading, and its battery, as its last report gave it (the simulated chair's battery model).
                try {
                    browser.until(d -> {
                        List<String> rows = d.findElement(By.id("chairs")).getText().lines().filter(l -> l.matches("chair[0-9]+ .*")).toList();
                        return !rows.isEmpty() && rows.stream().allMatch(l -> l.matches(".*\\(-?[0-9]+\\.[0-9], -?[0-9]+\\.[0-9]\\) -?[0-9]+° .* m/s [0-9]+\\.[0-9] V .*"));
                    });
                } catch (org.openqa.selenium.TimeoutException e) {
                    throw new AssertionError("chairs: " + browser.driver.findElement(By.id("chairs")).getText(), e);
                }
                browser.until(d -> d.findElements(By.cssSelector("polyline[id^='door-'][data-state='open']")).size() > 0);
                browser.until(d -> d.findElement(By.id("transports")).getText().contains("agreed"));
                // Resume for a chair that is not held is refused, saying so (an operator must not believe something was held).
                browser.until(d -> d.findElement(By.id("action-resume"))).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().contains("chair1 is not held: it is armed"));
                browser.screenshot("hospital-console");
                assertTrue(browser.driver.findElement(By.id("bids")).getText().contains("chair1"));
                theAuditTrailAndATransportsStory(browser);
                replayShowsTheChairWhereItWas(console, browser, recording);
            }
        }
    }

    /**
     * The audit trail: the transport asked on the page is there with who asked and from where (the
     * page's own address), its chair and its phases; filtered, the CSV export holds what is kept;
     * a click on it shows its story, from the call for proposals on.
     */
    private static void theAuditTrailAndATransportsStory(Browser browser) {
        browser.until(d -> {
            try {
                String row = d.findElement(By.cssSelector("#audit tr[data-key='T1']")).getText();
                return row.contains("desk@hospital-ui (desk-1), operator an operator at the console, console client 127.0.0.1:") && row.contains("control-chair1");
            } catch (org.openqa.selenium.NoSuchElementException | org.openqa.selenium.StaleElementReferenceException e) {
                return false;
            }
        });
        WebElement filter = browser.driver.findElement(By.cssSelector("#tw-audit .table-filter"));
        filter.sendKeys("T9");
        browser.until(d -> d.findElements(By.cssSelector("#audit tr[data-key]")).isEmpty());
        filter.clear();
        filter.sendKeys("T1");
        browser.until(d -> !d.findElements(By.cssSelector("#audit tr[data-key='T1']")).isEmpty());
        String csv = java.net.URLDecoder.decode(browser.driver.findElement(By.cssSelector("#tw-audit .table-csv")).getAttribute("href")
                .substring("data:text/csv;charset=utf-8,".length()), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(csv.startsWith("task,asked_by,conversation,origin,asked_at,from,to,priority,chair,auctions,awarded,")
                && csv.contains("\r\nT1,desk@hospital-ui,desk-1,127.0.0.1:") && csv.contains(",3,9,3,control-chair1,"), csv
                + "\ntable: " + browser.driver.findElement(By.id("audit")).getText());
        browser.until(d -> {
            try {
                d.findElement(By.cssSelector("#audit tr[data-key='T1']")).click();
                return true;
            } catch (org.openqa.selenium.StaleElementReferenceException e) {
                return false;
            }
        });
        browser.until(d -> {
            try {
                String story = d.findElement(By.id("story")).getText();
                return story.contains("CFP T1") && story.contains("ACCEPT control-chair1 for T1");
            } catch (org.openqa.selenium.NoSuchElementException | org.openqa.selenium.StaleElementReferenceException e) {
                return false;
            }
        });
        ((org.openqa.selenium.JavascriptExecutor) browser.driver).executeScript("document.getElementById('tw-audit').scrollIntoView()");
        browser.screenshot("hospital-audit");
    }

    /**
     * The run so far, recorded from its start, played back: with the slider at a time when the
     * chair was under way, the page shows it where the recorded snapshot had it, and its door as it was.
     */
    private static void replayShowsTheChairWhereItWas(Console console, Browser browser, String recording) throws Exception {
        assertTrue(console.stopRecording().startsWith(recording + ": "));
        java.util.List<com.fasterxml.jackson.databind.JsonNode> lines = Browser.recording(recording);
        long t0 = lines.get(0).get("t").asLong();
        java.util.List<com.fasterxml.jackson.databind.JsonNode> views = lines.stream()
                .filter(n -> n.get("topic").asText().equals("view-hospital")).toList();
        // A snapshot with the chair away from where it started, the last of its millisecond.
        com.fasterxml.jackson.databind.JsonNode first = chair(views.get(0));
        int k = views.size() * 2 / 3;
        while (k > 0 && (chair(views.get(k)).get("data").get("x").equals(first.get("data").get("x"))
                || k + 1 < views.size() && views.get(k + 1).get("t").asLong() == views.get(k).get("t").asLong())) {
            k--;
        }
        com.fasterxml.jackson.databind.JsonNode want = chair(views.get(k));
        long at = views.get(k).get("t").asLong();
        browser.driver.findElement(By.cssSelector("nav button[data-tab='replay']")).click();
        browser.until(d -> d.findElement(By.cssSelector("#recordings a[data-recording='" + recording + "']"))).click();
        browser.until(d -> d.findElement(By.id("replay-bar")).isDisplayed());
        browser.driver.findElement(By.cssSelector("nav button[data-view='hospital']")).click();
        browser.slideTo(t0, at);
        WebElement c = browser.driver.findElement(By.id("chair-chair1"));
        assertTrue(want.get("data").get("x").asText().equals(c.getAttribute("data-x"))
                && want.get("data").get("y").asText().equals(c.getAttribute("data-y")),
                "replayed at " + (at - t0) + " ms: the chair at (" + c.getAttribute("data-x") + ", " + c.getAttribute("data-y")
                        + "), recorded at " + want.get("data"));
        browser.screenshot("hospital-replay");
    }

    private static com.fasterxml.jackson.databind.JsonNode chair(com.fasterxml.jackson.databind.JsonNode view) {
        for (com.fasterxml.jackson.databind.JsonNode s : view.get("data").get("shapes")) {
            if ("chair-chair1".equals(s.path("id").asText())) {
                return s;
            }
        }
        throw new AssertionError("no chair1 in a recorded snapshot");
    }

    /**
     * An e-stop pressed and released mid-transport: the console shows the chair held and that it
     * needs a resume; the chair stands until the operator presses Resume on the page.
     */
    @Test
    void aChairHeldByItsEstopDrivesOnOnlyWhenTheOperatorResumesItInTheBrowser() throws Exception {
        HospitalMap map = HospitalMap.defaultHospital();
        try (Platform platform = Platform.builder().name("hospital-ui2").ports(new PortRange(7621, 80, 10)).build()) {
            HospitalWorld world = HospitalWorld.builder(map).seed(2010).build();
            io.concord.sim.world.SimChair simChair = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
            Hospital hospital = Hospital.start(platform, world, line -> { });
            world.attach(platform.runtime(), 20);
            MedicalAgent medical = new MedicalAgent(line -> { });
            platform.startAgent("medical", medical);
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            platform.startAgent("desk", desk);
            try (Console console = Console.start(platform, Console.Config.port(0));
                 Browser browser = new Browser()) {
                console.addView(new HospitalView(world, hospital, desk));
                while (!onLoop(platform, hospital::ready)) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
                medical.transport(19, 3, 0, 1);
                while (onLoop(platform, simChair::distanceTravelled) < 0.5) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
                onLoop(platform, () -> {
                    simChair.emergencyStop(true);
                    return null;
                });
                while (onLoop(platform, () -> hospital.control("chair1").supervisor().state()) != io.concord.agents.chair.ChairSupervisor.State.HELD) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
                onLoop(platform, () -> {
                    simChair.emergencyStop(false);
                    return null;
                });
                browser.driver.get(console.uri());
                browser.until(d -> d.findElement(By.cssSelector("nav button[data-view='hospital']"))).click();
                browser.until(d -> d.findElement(By.id("chairs")).getText().contains("the e-stop was pressed; needs Resume"));
                // On the map too: a red ring round the held chair.
                browser.until(d -> d.findElements(By.cssSelector("circle#chair-chair1[data-safety='held'][stroke='#c0392b']")).size() == 1);
                double held = onLoop(platform, simChair::distanceTravelled);
                // Two seconds of hospital time at 20 times real time: the chair stands.
                double t0 = onLoop(platform, () -> world.worldTimeNs() / 1e9);
                while (onLoop(platform, () -> world.worldTimeNs() / 1e9) < t0 + 2) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
                assertTrue(onLoop(platform, simChair::distanceTravelled) - held < 0.05, "released, not resumed: the chair stands");
                browser.screenshot("hospital-held");
                browser.until(d -> d.findElement(By.id("action-resume"))).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("chair1 resumes"));
                browser.until(d -> d.findElement(By.id("chairs")).getText().contains("armed"));
                while (onLoop(platform, simChair::distanceTravelled) < held + 0.3) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
            }
        }
    }

    /**
     * The operator's actions in the browser: a transport asked by room names (an unknown name
     * refused, naming the rooms); Stop all holds every chair, the idle one too, until the
     * operator resumes each; a transport cancelled while its chair drives to the pick-up, ended
     * in the audit trail with the operator's name; a transport whose patient is on board is not
     * cancelled, by the console nor by the Medical agent, each saying why.
     */
    @Test
    void theOperatorAsksByRoomStopsEveryChairAndCancelsATransportButNeverLeavesAPatient() throws Exception {
        HospitalMap map = HospitalMap.defaultHospital();
        try (Platform platform = Platform.builder().name("hospital-ops").ports(new PortRange(7721, 80, 10)).build()) {
            HospitalWorld world = HospitalWorld.builder(map).seed(2010).build();
            io.concord.sim.world.SimChair chair1 = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
            io.concord.sim.world.SimChair chair2 = world.addChair("chair2", ChairConfig.standard(), world.poseAt(23, 90));
            Hospital hospital = Hospital.start(platform, world, line -> { });
            hospital.operatorKey(io.concord.layers.authority.OperatorKey.generate("nurse Ada"));
            world.attach(platform.runtime(), 4);
            MedicalAgent medical = new MedicalAgent(line -> { }).operators(hospital.wardOperators());
            platform.startAgent("medical", medical);
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            platform.startAgent("desk", desk);
            try (Console console = Console.start(platform, Console.Config.port(0));
                 Browser browser = new Browser()) {
                console.addView(new HospitalView(world, hospital, desk));
                while (!onLoop(platform, hospital::ready)) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
                // The actions keep the console's guards: a GET is 405 (Allow: POST), a POST without the page's header 403.
                java.net.http.HttpClient http = java.net.http.HttpClient.newHttpClient();
                for (String action : java.util.List.of("cancel", "stop-all")) {
                    java.net.http.HttpResponse<String> get = http.send(java.net.http.HttpRequest.newBuilder(
                            java.net.URI.create(console.uri() + "api/views/hospital/" + action)).GET().build(),
                            java.net.http.HttpResponse.BodyHandlers.ofString());
                    assertTrue(get.statusCode() == 405 && get.headers().firstValue("Allow").orElse("").equals("POST"), action + ": " + get.statusCode());
                    java.net.http.HttpResponse<String> bare = http.send(java.net.http.HttpRequest.newBuilder(
                            java.net.URI.create(console.uri() + "api/views/hospital/" + action)).POST(java.net.http.HttpRequest.BodyPublishers.ofString("task=T1"))
                            .header("Content-Type", "application/x-www-form-urlencoded").build(), java.net.http.HttpResponse.BodyHandlers.ofString());
                    assertTrue(bare.statusCode() == 403, action + " without the header: " + bare.statusCode());
                }
                browser.driver.get(console.uri());
                browser.until(d -> d.findElement(By.cssSelector("nav button[data-view='hospital']"))).click();
                // Rooms by name: an unknown one is refused, naming the rooms; A2 and B7 are nodes 3 and 9.
                field(browser, "from", "Z9");
                browser.driver.findElement(By.id("action-transport")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("no node or room 'Z9' in ")
                        && d.findElement(By.id("view-said")).getText().contains("rooms: A1, A2, A3"));
                field(browser, "from", "A2");
                field(browser, "to", "Room B7");
                browser.driver.findElement(By.id("action-transport")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("asked medical for a transport from node 3 to node 9"));
                browser.until(d -> d.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.contains("T1") && l.contains("to_pickup")));
                // Stop all: both chairs held by the operator's stop, on the page and on the map.
                browser.driver.findElement(By.id("action-stop-all")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText()
                        .equals("stopped 2 chairs (chair1, chair2): each stays held until an operator resumes it"));
                browser.until(d -> d.findElement(By.id("chairs")).getText().lines()
                        .filter(l -> l.contains("held: an operator stopped it (stop all by operator nurse Ada at console client 127.0.0.1:")
                                && l.contains("needs Resume")).count() == 2);
                browser.until(d -> d.findElements(By.cssSelector("circle[id^='chair-chair'][data-safety='held'][stroke='#c0392b']")).size() == 2);
                browser.screenshot("hospital-stop-all");
                double held1 = onLoop(platform, chair1::distanceTravelled);
                double held2 = onLoop(platform, chair2::distanceTravelled);
                double t0 = onLoop(platform, () -> world.worldTimeNs() / 1e9);
                while (onLoop(platform, () -> world.worldTimeNs() / 1e9) < t0 + 3) {
                    Thread.sleep(20);   // polling the loop, not waiting for time to pass
                }
                assertTrue(onLoop(platform, chair1::distanceTravelled) - held1 < 0.05, "stopped, not resumed: chair1 stands");
                assertTrue(onLoop(platform, chair2::distanceTravelled) - held2 < 0.05, "stopped: chair2 stands");
                // Neither agent resumed its chair by itself, with a task (chair1) or without (chair2).
                for (String c : java.util.List.of("chair1", "chair2")) {
                    assertTrue(onLoop(platform, () -> hospital.control(c).supervisor().state()) == io.concord.agents.chair.ChairSupervisor.State.HELD,
                            c + " is still held by the operator's stop");
                }
                assertTrue(browser.driver.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.contains("T1") && l.contains("to_pickup")),
                        "T1 was stopped on its way to the pick-up: " + browser.driver.findElement(By.id("bids")).getText());
                // Cancelled on its way to the pick-up: withdrawn, the chair drops it, the audit says who.
                field(browser, "task", "T1");
                field(browser, "reason", "the patient went home");
                browser.driver.findElement(By.id("action-cancel")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().equals("asked medical to withdraw T1 (cancel-1)"));
                browser.until(d -> d.findElement(By.id("cancels")).getText().lines().anyMatch(l -> l.contains("cancel-1") && l.contains("withdrawn")));
                browser.until(d -> d.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.contains("T1") && l.contains("cancelled")));
                // The transport asked here says it was withdrawn and why, not "failed ... by control-chair1".
                browser.until(d -> d.findElement(By.id("transports")).getText().lines()
                        .anyMatch(l -> l.startsWith("desk-1") && l.contains("withdrawn T1: withdrawn: the patient went home")));
                browser.until(d -> {
                    String row = d.findElement(By.cssSelector("#audit tr[data-key='T1']")).getText();
                    return row.contains("desk@hospital-ops (desk-1), operator nurse Ada, console client 127.0.0.1:")
                            && row.contains("withdrawn: the patient went home (operator nurse Ada at console client 127.0.0.1:");
                });
                // The operator resumes each chair.
                for (String c : java.util.List.of("chair1", "chair2")) {
                    field(browser, "chair", c);
                    browser.driver.findElement(By.id("action-resume")).click();
                    browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith(c + " resumes"));
                }
                browser.until(d -> d.findElement(By.id("chairs")).getText().lines().filter(l -> l.contains(" armed")).count() == 2);
                // A transport whose patient is on board is never withdrawn: the console refuses, saying why ...
                field(browser, "from", "A2");
                field(browser, "to", "B7");
                field(browser, "unload", "900");
                browser.driver.findElement(By.id("action-transport")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("asked medical for a transport from node 3 to node 9 (desk-2)"));
                browser.until(d -> d.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.contains("T2") && l.contains("loading")));
                field(browser, "task", "T2");
                browser.driver.findElement(By.id("action-cancel")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().matches(
                        "T2 is not cancelled: its patient is on board chair[12] \\(loading\\), which drives on to the drop-off at node 9; .*"));
                // ... and so does the Medical agent, asked over ACL whatever the console checked.
                onLoop(platform, () -> desk.cancel("T2", "asked past the console"));
                browser.until(d -> d.findElement(By.id("cancels")).getText().lines().anyMatch(l -> l.contains("cancel-2") && l.contains("refused")
                        && l.contains("T2's patient is on board control-chair")));
                assertTrue(browser.driver.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.contains("T2") && l.contains("loading")),
                        "T2 goes on: " + browser.driver.findElement(By.id("bids")).getText());
                // A transport the staff asked for at the Medical agent (as the demo's --tasks do), not at this desk:
                // the console's cancel carries the operator's signed order, and the Medical agent withdraws it.
                var staffs = medical.transport(map.nodeNamed("A3"), 9, 0, 60);
                browser.until(d -> d.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.contains("T3") && l.contains("to_pickup")));
                // Stopped and resumed on its way: the Medical agent's story of T3 says who stopped it and who resumed it.
                browser.driver.findElement(By.id("action-stop-all")).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("stopped 2 chairs"));
                browser.until(d -> d.findElements(By.cssSelector("circle[id^='chair-chair'][data-safety='held']")).size() == 2);
                for (String c : java.util.List.of("chair1", "chair2")) {
                    field(browser, "chair", c);
                    browser.driver.findElement(By.id("action-resume")).click();
                    browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith(c + " resumes"));
                }
                field(browser, "task", "T3");
                field(browser, "reason", "the ward called it off");
                browser.driver.findElement(By.id("action-cancel")).click();
                browser.until(d -> d.findElement(By.id("cancels")).getText().lines().anyMatch(l -> l.contains("cancel-3") && l.contains("withdrawn")));
                assertTrue(staffs.get(30, TimeUnit.SECONDS).reason().startsWith("withdrawn: the ward called it off (operator nurse Ada at console client 127.0.0.1:"),
                        staffs.join().reason());
                assertTrue(staffs.join().reason().endsWith("(by operator nurse Ada, asked by desk)"), staffs.join().reason());
                try {
                    browser.until(d -> {
                        try {
                            d.findElement(By.cssSelector("#audit tr[data-key='T3']")).click();
                            String story = d.findElement(By.id("story")).getText();
                            return story.contains("T3 paused on control-chair") && story.contains("stop all by operator nurse Ada at console client 127.0.0.1:")
                                    && story.contains("T3 resumed on control-chair") && story.contains("decided by nurse Ada")
                                    && story.contains("T3 withdrawn: the ward called it off");
                        } catch (org.openqa.selenium.NoSuchElementException | org.openqa.selenium.StaleElementReferenceException e) {
                            return false;
                        }
                    });
                } catch (org.openqa.selenium.TimeoutException e) {
                    throw new AssertionError("T3's story: " + browser.driver.findElement(By.id("story")).getText(), e);
                }
                browser.screenshot("hospital-operator");
            }
        }
    }

    /** Types a value into the view's form field of that name. */
    private static void field(Browser browser, String name, String value) {
        WebElement in = browser.until(d -> d.findElement(By.cssSelector("#view-form input[name='" + name + "']")));
        in.clear();
        in.sendKeys(value);
    }

    private static <T> T onLoop(Platform platform, java.util.function.Supplier<T> s) throws Exception {
        CompletableFuture<T> f = new CompletableFuture<>();
        platform.runtime().execute(() -> f.complete(s.get()));
        return f.get(10, TimeUnit.SECONDS);
    }
}
