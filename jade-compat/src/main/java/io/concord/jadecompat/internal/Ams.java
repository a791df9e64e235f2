package io.concord.jadecompat.internal;

import jade.content.Concept;
import jade.content.ContentElement;
import jade.content.ContentManager;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.Result;
import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.domain.JADEAgentManagement.CreateAgent;
import jade.domain.JADEAgentManagement.JADEManagementOntology;
import jade.domain.JADEAgentManagement.KillAgent;
import jade.domain.JADEAgentManagement.QueryAgentsOnLocation;
import jade.domain.JADEAgentManagement.ShutdownPlatform;
import jade.lang.acl.ACLMessage;
import jade.core.Location;
import jade.wrapper.ContainerController;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayList;
import java.util.List;

/**
 * JADE's AMS for the agent-management actions of {@link JADEManagementOntology}, carried out in
 * this JVM over Concord's runtime: a REQUEST to {@code ams} in that ontology never leaves the
 * sending agent; its answer (INFORM with {@code Done} or {@code Result}, FAILURE, NOT_UNDERSTOOD,
 * as JADE's AMS answers) is put in the sender's queue as from {@code ams}. Agents of other JVMs
 * and containers of other JVMs are not reached (FAILURE).
 */
public final class Ams {
    private static final Logger LOG = LoggerFactory.getLogger(Ams.class);
    /** The container JADE puts its AMS and DF on; here they are the platform's, and are listed there. */
    static final String MAIN = "Main-Container";

    private Ams() {
    }

    /** True for a REQUEST to the AMS alone in JADE's agent-management ontology. */
    public static boolean handles(ACLMessage m) {
        if (m.getPerformative() != ACLMessage.REQUEST || !JADEManagementOntology.NAME.equalsIgnoreCase(m.getOntology())) {
            return false;
        }
        jade.util.leap.Iterator it = m.getAllReceiver();
        if (!it.hasNext()) {
            return false;
        }
        AID r = (AID) it.next();
        return !it.hasNext() && "ams".equalsIgnoreCase(r.getLocalName());
    }

    /** Carries out the request for {@code sender} and puts the AMS's answer in its queue. */
    public static void serve(Agent sender, Engine engine, ACLMessage request) {
        ACLMessage reply = request.createReply();
        reply.setSender(sender.getAMS());
        ContentManager cm = new ContentManager();
        String language = request.getLanguage() == null ? FIPANames.ContentLanguage.FIPA_SL : request.getLanguage();
        cm.registerLanguage(new SLCodec(), language);
        cm.registerOntology(JADEManagementOntology.getInstance());
        Runnable after = null;
        try {
            ContentElement ce = cm.extractContent(request);
            if (!(ce instanceof Action)) {
                throw new IllegalArgumentException("the content is not an action");
            }
            Action act = (Action) ce;
            Concept what = act.getAction();
            if (what instanceof KillAgent k) {
                Agent target = k.getAgent() == null ? null : engine.jadeAgent(k.getAgent().getLocalName());
                if (target == null) {
                    fail(reply, "agent " + (k.getAgent() == null ? null : k.getAgent().getName()) + " not found on this JVM's containers");
                } else {
                    target.doDelete();
                    inform(cm, reply, new Done(act));
                }
            } else if (what instanceof CreateAgent c) {
                ContainerController where = c.getContainer() == null ? sender.getContainerController()
                        : engine.container(c.getContainer().getName());
                if (where == null) {
                    fail(reply, "container " + c.getContainer().getName() + " not found in this JVM");
                } else {
                    List<Object> args = new ArrayList<>();
                    for (jade.util.leap.Iterator it = c.getAllArguments(); it.hasNext(); ) {
                        args.add(it.next());
                    }
                    try {
                        where.createNewAgent(c.getAgentName(), c.getClassName(), args.toArray()).start();
                        inform(cm, reply, new Done(act));
                    } catch (jade.wrapper.StaleProxyException e) {
                        fail(reply, e.getMessage());
                    }
                }
            } else if (what instanceof QueryAgentsOnLocation q) {
                String name = q.getLocation() == null ? null : q.getLocation().getName();
                if (name == null || engine.container(name) == null) {
                    fail(reply, "container " + name + " not found in this JVM");
                } else {
                    jade.util.leap.List aids = new jade.util.leap.ArrayList();
                    if (MAIN.equalsIgnoreCase(name)) {
                        aids.add(sender.getAMS());
                        aids.add(sender.getDefaultDF());
                    }
                    for (Agent a : engine.jadeAgents()) {
                        Location where = a.here();
                        if (where != null && where.getName().equals(name) && !AgentAccess.get().ending(a)) {
                            aids.add(a.getAID());
                        }
                    }
                    inform(cm, reply, new Result(act, aids));
                }
            } else if (what instanceof ShutdownPlatform) {
                inform(cm, reply, new Done(act));
                after = () -> shutDown(engine);
            } else {
                reply.setPerformative(ACLMessage.REFUSE);
                reply.setContent("(unsupported-act " + what.getClass().getSimpleName() + ")");
            }
        } catch (jade.content.lang.Codec.CodecException | jade.content.onto.OntologyException | RuntimeException e) {
            LOG.debug("AMS: cannot read {}", request.getContent(), e);
            reply.setPerformative(ACLMessage.NOT_UNDERSTOOD);
            reply.setContent("(unrecognised-value content)");
        }
        sender.postMessage(reply);
        if (after != null) {
            Thread t = new Thread(after, "concord-jade-shutdown");
            t.start();
        }
    }

    private static void inform(ContentManager cm, ACLMessage reply, ContentElement ce) throws jade.content.lang.Codec.CodecException,
            jade.content.onto.OntologyException {
        reply.setPerformative(ACLMessage.INFORM);
        cm.fillContent(reply, ce);
    }

    private static void fail(ACLMessage reply, String why) {
        reply.setPerformative(ACLMessage.FAILURE);
        reply.setContent("(internal-error \"" + why.replace("\"", "'") + "\")");
    }

    /** Kills every container of this JVM (their agents' takeDown runs), then stops the platform. */
    private static void shutDown(Engine engine) {
        for (ContainerController c : engine.containers()) {
            try {
                c.kill();
            } catch (jade.wrapper.StaleProxyException e) {
                LOG.warn("shutdown: container {} did not stop cleanly: {}", c, e.toString());
            }
        }
        Engine.shutDown();
    }
}
