package io.concord.jadecompat.internal;

import jade.core.AID;
import jade.core.Agent;
import jade.core.ServiceException;
import jade.core.messaging.TopicManagementHelper;
import jade.core.messaging.TopicUtility;
import jade.lang.acl.ACLMessage;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * JADE's topics over concord-jade: which agents of this JVM are registered for which topic, and
 * the delivery of a message sent to a topic to each of them (the message as sent, its receivers
 * naming the topic, so that {@code MatchTopic} finds it). Agents of other JVMs are not reached.
 */
public final class Topics implements TopicManagementHelper {
    /** Topic name to the local names of the agents registered for it. */
    private static final Map<String, Set<String>> REGISTERED = new ConcurrentHashMap<>();
    private Agent agent;

    public Topics() {
    }

    @Override
    public void init(Agent a) {
        this.agent = a;
    }

    @Override
    public AID createTopic(String topicName) {
        return TopicUtility.createTopic(topicName);
    }

    @Override
    public boolean isTopic(AID id) {
        return TopicUtility.isTopic(id);
    }

    @Override
    public void register(AID topic) throws ServiceException {
        register(agent.getAID(), topic);
    }

    @Override
    public void register(AID aid, AID topic) throws ServiceException {
        if (!isTopic(topic)) {
            throw new ServiceException(topic + " is not a topic");
        }
        REGISTERED.computeIfAbsent(topic.getName(), k -> ConcurrentHashMap.newKeySet()).add(aid.getLocalName());
    }

    @Override
    public void deregister(AID topic) throws ServiceException {
        deregister(agent.getAID(), topic);
    }

    @Override
    public void deregister(AID aid, AID topic) throws ServiceException {
        Set<String> s = REGISTERED.get(topic.getName());
        if (s != null) {
            s.remove(aid.getLocalName());
        }
    }

    /** An agent ended: it reads no topic any more. */
    public static void ended(String localName) {
        for (Set<String> s : REGISTERED.values()) {
            s.remove(localName);
        }
    }

    /**
     * Delivers a message to the agents registered for the topics among its receivers; returns the
     * receivers that are not topics (the caller sends to them as usual), or null if there were no topics.
     */
    public static List<AID> deliver(Engine engine, ACLMessage m) {
        List<AID> others = new ArrayList<>();
        Set<String> readers = new java.util.LinkedHashSet<>();
        boolean topics = false;
        for (jade.util.leap.Iterator it = m.getAllReceiver(); it.hasNext(); ) {
            AID r = (AID) it.next();
            if (TopicUtility.isTopic(r)) {
                topics = true;
                Set<String> s = REGISTERED.get(r.getName());
                if (s != null) {
                    readers.addAll(s);
                }
            } else {
                others.add(r);
            }
        }
        if (!topics) {
            return null;
        }
        for (String n : readers) {
            Agent a = engine.jadeAgent(n);
            if (a != null) {
                ACLMessage copy = (ACLMessage) m.clone();
                copy.setPostTimeStamp();
                a.postMessage(copy);
            }
        }
        return others;
    }
}
